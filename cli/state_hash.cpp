#include "cli/state_hash.h"

#include <cstdio>
#include <cstring>

#include "engine/world.h"

namespace physdbg::cli {
namespace {

// FNV-1a over the raw bytes: simple, stable across platforms with IEEE doubles.
void mix(std::uint64_t& hash, double value) {
  unsigned char bytes[sizeof value];
  std::memcpy(bytes, &value, sizeof value);
  for (unsigned char byte : bytes) {
    hash ^= byte;
    hash *= 0x100000001b3ull;
  }
}

void mix(std::uint64_t& hash, const Vec3& v) {
  for (int i = 0; i < 3; ++i) mix(hash, v[i]);
}

}  // namespace

std::uint64_t worldStateHash(const World& world) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const RigidBody& body : world.bodies()) {
    mix(hash, body.position());
    const Quat& q = body.orientation();
    for (double value : {q.w(), q.x(), q.y(), q.z()}) mix(hash, value);
    mix(hash, body.linearVelocity());
    mix(hash, body.angularVelocity());
  }
  return hash;
}

std::string hexHash(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace physdbg::cli
