#include "engine/solver/wide_contact_rows.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace physdbg {
namespace {

using simd::Lanes;
constexpr int lanes = simd::width;
constexpr int slots = ContactManifold::maxPoints;

using simd::getLane;

// The velocities of one side's bodies, lane by lane (zero in empty lanes):
// v[0..2] linear, v[3..5] angular. A body's six velocities are one run of
// doubles (BodyMotion keeps angularVelocity right after linearVelocity), read
// as whole packets from every lane's body and transposed, so the lanes fill
// without a round trip through memory. Packets start at 0, W, 2W, ... and the
// last one ends at the sixth double (with 4 lanes: at 0 and 2, overlapping).
struct LaneVelocities {
  Lanes v[6];
  const Lanes* linear() const { return v; }
  const Lanes* angular() const { return v + 3; }
};

alignas(64) constexpr double noVelocity[6] = {};  // an empty lane's

const double* velocities(const BodyMotion& motion) {
  assert(motion.angularVelocity.data() == motion.linearVelocity.data() + 3);
  return motion.linearVelocity.data();
}

[[gnu::always_inline]] inline LaneVelocities gather(const std::array<std::uint32_t, lanes>& ids,
                                                    const std::vector<SolverBody>& bodies) {
  const double* rows[lanes];
  for (int lane = 0; lane < lanes; ++lane)
    rows[lane] = ids[lane] == WideManifolds::empty ? noVelocity : velocities(bodies[ids[lane]].motion);
  LaneVelocities result;
  simd::gatherRuns<6>(rows, result.v);
  return result;
}

// Only movable bodies are written: an immovable one (the floor) may sit in
// several lanes, groups and islands at once, and its velocity never changes.
[[gnu::always_inline]] inline void scatter(const LaneVelocities& velocities,
                                           const std::array<std::uint32_t, lanes>& ids,
                                           const std::array<bool, lanes>& writable, std::vector<SolverBody>& bodies) {
  for (int b = 0; b < simd::runBlocks(6); ++b) {
    const int start = simd::runBlockStart(6, b);
    Lanes block[lanes];
    for (int i = 0; i < lanes; ++i) block[i] = velocities.v[start + i];
    simd::transpose(block);
    for (int lane = 0; lane < lanes; ++lane)
      if (writable[lane]) block[lane].store(bodies[ids[lane]].motion.linearVelocity.data() + start);
  }
}

[[gnu::always_inline]] inline Lanes dot(const Lanes* x, const Lanes* y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// The relative velocity along a row, as the scalar solver's rowVelocity.
[[gnu::always_inline]] inline Lanes rowVelocity(const LaneVelocities& a, const LaneVelocities& b,
                                                const WideManifolds& group, const WidePoint& point, int row) {
  Lanes difference[3];
  for (int axis = 0; axis < 3; ++axis) difference[axis] = b.linear()[axis] - a.linear()[axis];
  return dot(difference, group.direction[row]) + dot(b.angular(), point.crossB[row]) -
         dot(a.angular(), point.crossA[row]);
}

// `locks`: some lane has a locked linear axis. Without, every mask is 1 and
// multiplying by it changes no bit, so it is left out.
template <bool locks>
[[gnu::always_inline]] inline void applyRow(LaneVelocities& a, LaneVelocities& b, const WideManifolds& group,
                                            const WidePoint& point, int row, Lanes impulse) {
  const Lanes linearA = group.inverseMassA * impulse, linearB = group.inverseMassB * impulse;
  for (int axis = 0; axis < 3; ++axis) {
    const Lanes direction = group.direction[row][axis];
    a.v[axis] -= linearA * (locks ? direction * group.linearMaskA[axis] : direction);
    a.v[3 + axis] -= impulse * point.turnA[row][axis];
    b.v[axis] += linearB * (locks ? direction * group.linearMaskB[axis] : direction);
    b.v[3 + axis] += impulse * point.turnB[row][axis];
  }
}

template <bool locks>
void applyNormal(LaneVelocities& a, LaneVelocities& b, const WideManifolds& group, WidePoint& point, Lanes impulse) {
  applyRow<locks>(a, b, group, point, 0, impulse);
  point.stepNormalImpulse += impulse;
}

template <bool locks>
void solveNormal(LaneVelocities& a, LaneVelocities& b, const WideManifolds& group, WidePoint& point,
                 const WideSweep& sweep) {
  const Softness& softness = sweep.substeps->softness;
  const Lanes zero = Lanes::zero(), one = Lanes::all(1.0);
  const Lanes apart = simd::greater(point.gap, zero);
  const Lanes closing = point.gap / Lanes::all(sweep.substeps->h);
  Lanes bias = simd::select(apart, closing, zero), massScale = one, impulseScale = zero;
  if (sweep.useBias) {
    const Lanes push = simd::max(Lanes::all(softness.biasRate) * point.gap, Lanes::all(-sweep.maxPushSpeed));
    bias = simd::select(apart, closing, push);
    massScale = simd::select(apart, one, Lanes::all(softness.massScale));
    impulseScale = simd::select(apart, zero, Lanes::all(softness.impulseScale));
  }
  const Lanes normalVelocity = rowVelocity(a, b, group, point, 0);
  const Lanes impulse = -point.normalMass * massScale * (normalVelocity + bias) - impulseScale * point.normalImpulse;
  const Lanes total = simd::max(point.normalImpulse + impulse, zero);
  applyNormal<locks>(a, b, group, point, total - point.normalImpulse);
  point.normalImpulse = total;
  point.largestImpulse = simd::max(point.largestImpulse, total);
}

template <bool locks>
void solveFriction(LaneVelocities& a, LaneVelocities& b, const WideManifolds& group, WidePoint& point) {
  Lanes tangent[2];
  for (int t = 0; t < 2; ++t)
    tangent[t] = point.tangentImpulse[t] - point.tangentMass[t] * rowVelocity(a, b, group, point, t + 1);
  const Lanes limit = point.friction * point.normalImpulse;
  const Lanes squared = tangent[0] * tangent[0] + tangent[1] * tangent[1];
  const Lanes clamp = simd::both(simd::greater(squared, limit * limit), simd::greater(squared, Lanes::zero()));
  // Resting contacts stick: most sweeps clamp no lane, and the square root
  // and division were a fifth of the whole wide solve.
  if (simd::any(clamp)) {
    const Lanes scale = limit / simd::sqrt(simd::select(clamp, squared, Lanes::all(1.0)));
    for (int t = 0; t < 2; ++t) tangent[t] = simd::select(clamp, tangent[t] * scale, tangent[t]);
  }
  applyRow<locks>(a, b, group, point, 1, tangent[0] - point.tangentImpulse[0]);
  applyRow<locks>(a, b, group, point, 2, tangent[1] - point.tangentImpulse[1]);
  point.tangentImpulse[0] = tangent[0];
  point.tangentImpulse[1] = tangent[1];
}

}  // namespace

namespace {

template <bool locks>
void warmStartGroup(WideManifolds& group, std::vector<SolverBody>& bodies) {
  LaneVelocities a = gather(group.bodyA, bodies), b = gather(group.bodyB, bodies);
  for (int p = 0; p < group.pointSlots; ++p) {
    WidePoint& point = group.points[p];
    applyNormal<locks>(a, b, group, point, point.normalImpulse);
    applyRow<locks>(a, b, group, point, 1, point.tangentImpulse[0]);
    applyRow<locks>(a, b, group, point, 2, point.tangentImpulse[1]);
  }
  scatter(a, group.bodyA, group.writableA, bodies);
  scatter(b, group.bodyB, group.writableB, bodies);
}

template <bool locks>
void solveGroup(WideManifolds& group, std::vector<SolverBody>& bodies, const WideSweep& sweep) {
  LaneVelocities a = gather(group.bodyA, bodies), b = gather(group.bodyB, bodies);
  const int used = group.pointSlots;
  for (int visit = 0; visit < used; ++visit)
    solveNormal<locks>(a, b, group, group.points[sweep.reversed ? used - 1 - visit : visit], sweep);
  for (int visit = 0; visit < used; ++visit)
    solveFriction<locks>(a, b, group, group.points[sweep.reversed ? used - 1 - visit : visit]);
  scatter(a, group.bodyA, group.writableA, bodies);
  scatter(b, group.bodyB, group.writableB, bodies);
}

}  // namespace

void warmStartWide(WideManifolds& group, std::vector<SolverBody>& bodies) {
  if (group.linearLocks)
    warmStartGroup<true>(group, bodies);
  else
    warmStartGroup<false>(group, bodies);
}

void solveWide(WideManifolds& group, std::vector<SolverBody>& bodies, const WideSweep& sweep) {
  if (group.linearLocks)
    solveGroup<true>(group, bodies, sweep);
  else
    solveGroup<false>(group, bodies, sweep);
}

void storeWideImpulses(const WideManifolds& group, std::vector<ContactManifold>& manifolds,
                       std::vector<PointConstraint>& constraints, const std::vector<char>& kept) {
  for (int lane = 0; lane < lanes; ++lane) {
    const std::uint32_t m = group.manifold[lane];
    if (m == WideManifolds::empty) continue;
    ContactManifold& manifold = manifolds[m];
    for (int p = 0; p < manifold.pointCount; ++p) {
      const WidePoint& wide = group.points[p];
      ManifoldPoint& point = manifold.points[p];
      point.normalImpulse = getLane(wide.normalImpulse, lane);
      point.tangentImpulse[0] = getLane(wide.tangentImpulse[0], lane);
      point.tangentImpulse[1] = getLane(wide.tangentImpulse[1], lane);
      point.stepNormalImpulse = getLane(wide.stepNormalImpulse, lane);
      if (kept[m]) constraints[m * slots + p].largestImpulse = getLane(wide.largestImpulse, lane);
    }
  }
}

}  // namespace physdbg
