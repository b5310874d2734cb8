#pragma once
// Doubles side by side in one SIMD register, for the wide contact solve
// (wide_contact_rows.h): the few operations it needs, over Eigen's packet
// types so the code is the same on every instruction set. The width follows
// the compiler's target: 4 lanes with AVX (CMake's PHYSDBG_SIMD=avx2, the
// default), 2 with plain SSE2 (PHYSDBG_SIMD=sse2), 1 without vectorization.
// Each operation rounds exactly as the scalar one it stands for, so the wide
// solve matches the scalar one up to the order of a few sums.
#include <Eigen/Core>
#include <cstdint>
#include <cstring>

namespace physdbg::simd {

using Packet = Eigen::internal::packet_traits<double>::type;
inline constexpr int width = static_cast<int>(sizeof(Packet) / sizeof(double));

struct Lanes {
  Packet value;

  static Lanes all(double x) { return {Eigen::internal::pset1<Packet>(x)}; }
  static Lanes zero() { return all(0.0); }
  static Lanes load(const double* from) { return {Eigen::internal::ploadu<Packet>(from)}; }
  void store(double* to) const { Eigen::internal::pstoreu(to, value); }
};

inline Lanes operator+(Lanes a, Lanes b) { return {Eigen::internal::padd(a.value, b.value)}; }
inline Lanes operator-(Lanes a, Lanes b) { return {Eigen::internal::psub(a.value, b.value)}; }
inline Lanes operator*(Lanes a, Lanes b) { return {Eigen::internal::pmul(a.value, b.value)}; }
inline Lanes operator/(Lanes a, Lanes b) { return {Eigen::internal::pdiv(a.value, b.value)}; }
inline Lanes operator-(Lanes a) { return {Eigen::internal::pnegate(a.value)}; }
inline Lanes& operator+=(Lanes& a, Lanes b) { return a = a + b; }
inline Lanes& operator-=(Lanes& a, Lanes b) { return a = a - b; }

// As std::max(a, b) and std::min(a, b) lane by lane (a when they compare equal).
inline Lanes max(Lanes a, Lanes b) { return {Eigen::internal::pselect(Eigen::internal::pcmp_lt(a.value, b.value), b.value, a.value)}; }
inline Lanes min(Lanes a, Lanes b) { return {Eigen::internal::pselect(Eigen::internal::pcmp_lt(b.value, a.value), b.value, a.value)}; }
inline Lanes sqrt(Lanes a) { return {Eigen::internal::psqrt(a.value)}; }

// Masks: all bits set in a lane where the comparison holds.
inline Lanes greater(Lanes a, Lanes b) { return {Eigen::internal::pcmp_lt(b.value, a.value)}; }
inline Lanes both(Lanes a, Lanes b) { return {Eigen::internal::pand(a.value, b.value)}; }
// Whether `mask` is set in any lane: lets a rare branch (a friction clamp)
// skip its costly operations when no lane takes it.
inline bool any(Lanes mask) {
#if defined(EIGEN_VECTORIZE_AVX)
  return _mm256_movemask_pd(mask.value) != 0;
#elif defined(EIGEN_VECTORIZE_SSE2)
  return _mm_movemask_pd(mask.value) != 0;
#else
  std::uint64_t bits[width];
  std::memcpy(bits, &mask.value, sizeof bits);
  std::uint64_t set = 0;
  for (int i = 0; i < width; ++i) set |= bits[i];
  return set != 0;
#endif
}
// One lane of a register, read or written through memory (packing and
// unpacking, not the inner loops).
inline void setLane(Lanes& target, int lane, double value) {
  std::memcpy(reinterpret_cast<char*>(&target) + lane * sizeof(double), &value, sizeof value);
}
inline double getLane(const Lanes& source, int lane) {
  double value;
  std::memcpy(&value, reinterpret_cast<const char*>(&source) + lane * sizeof(double), sizeof value);
  return value;
}
// A mask lane: all bits set or none.
inline void setMaskLane(Lanes& target, int lane, bool set) {
  const std::uint64_t bits = set ? ~std::uint64_t{0} : 0;
  std::memcpy(reinterpret_cast<char*>(&target) + lane * sizeof(double), &bits, sizeof bits);
}
// Eigen's packets are vector types whose alignment attribute a template
// argument drops; PacketBlock is Eigen's own way to hold them, so that is fine.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wignored-attributes"
using PacketBlock = Eigen::internal::PacketBlock<Packet, width>;
#pragma GCC diagnostic pop

// width registers, each holding one lane's run, become width registers each
// holding one position of every lane's run (and back: it is its own inverse).
[[gnu::always_inline]] inline void transpose(Lanes* block) {
  if constexpr (width > 1) {
    PacketBlock packets;
    for (int i = 0; i < width; ++i) packets.packet[i] = block[i].value;
    Eigen::internal::ptranspose(packets);
    for (int i = 0; i < width; ++i) block[i].value = packets.packet[i];
  }
}

// Where the b-th packet of a run of `count` doubles starts: 0, W, 2W, ...,
// and the last one ends at the run's end (overlapping the one before).
constexpr int runBlocks(int count) { return (count + width - 1) / width; }
constexpr int runBlockStart(int count, int block) {
  return block * width + width <= count ? block * width : count - width;
}

// Lane l's run of `count` doubles at runs[l] into out[0, count), one
// register per position: whole packets read and transposed, no lane-by-lane
// inserts. Needs count >= width.
template <int count>
[[gnu::always_inline]] inline void gatherRuns(const double* const* runs, Lanes* out) {
  static_assert(count >= width, "a run shorter than a packet");
  for (int b = 0; b < runBlocks(count); ++b) {
    Lanes block[width];
    for (int lane = 0; lane < width; ++lane) block[lane] = Lanes::load(runs[lane] + runBlockStart(count, b));
    transpose(block);
    for (int i = 0; i < width; ++i) out[runBlockStart(count, b) + i] = block[i];
  }
}

// Lane by lane: `yes` where `mask` is set, else `no`.
inline Lanes select(Lanes mask, Lanes yes, Lanes no) { return {Eigen::internal::pselect(mask.value, yes.value, no.value)}; }

}  // namespace physdbg::simd
