#pragma once
// Up to four contact points between two bodies sharing one normal. One point
// cannot resist a tipping torque; four points spanning the touching faces can,
// which is what lets boxes stack. Points carry feature ids so the solver can
// warm-start them from the previous step's impulses.
#include <array>
#include <cstdint>

#include "engine/math.h"

namespace physdbg {

struct ManifoldPoint {
  Vec3 pointA = Vec3::Zero();  // on A's surface, world, at detection
  Vec3 pointB = Vec3::Zero();  // on B's surface, world, at detection
  Vec3 localA = Vec3::Zero();  // pointA in A's frame
  Vec3 localB = Vec3::Zero();  // pointB in B's frame
  // (pointB - pointA) . normal: negative when penetrating, positive for a
  // speculative point that is not yet touching.
  double separation = 0.0;
  std::uint32_t featureId = 0;

  // Accumulated impulses, kept across steps for warm starting: each is the
  // impulse of one substep (the last), so its force is normalImpulse over
  // the substep that island took, which the settings do not tell.
  double normalImpulse = 0.0;
  double tangentImpulse[2] = {0.0, 0.0};
  // The normal impulse the solver applied at this point over the whole step,
  // every substep and the restitution pass, N s: force = stepNormalImpulse /
  // dt whatever substeps its island took. Rebuilt by each step; display only.
  double stepNormalImpulse = 0.0;
};

struct ContactManifold {
  static constexpr int maxPoints = 4;
  std::uint32_t a = 0, b = 0;  // body ids, a < b
  Vec3 normal = Vec3::UnitY();  // from A to B, world
  int pointCount = 0;
  std::array<ManifoldPoint, maxPoints> points;
};

}  // namespace physdbg
