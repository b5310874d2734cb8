#pragma once
// Shared helpers for the narrow-phase tests: random rigid motions and checks
// that a contact result is finite and self-consistent.
#include <gtest/gtest.h>

#include <random>

#include "engine/narrowphase/narrow_phase.h"

namespace physdbg::testing {

inline Quat randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> gaussian(0.0, 1.0);
  Quat q(gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng));
  return q.normalized();
}

// world' = motion * world
inline Transform compose(const Transform& motion, const Transform& t) {
  return {motion.apply(t.position), (motion.rotation * t.rotation).normalized()};
}

inline void expectFinite(const ContactResult& r) {
  EXPECT_TRUE(std::isfinite(r.distance) && std::isfinite(r.depth));
  EXPECT_TRUE(isFinite(r.normal) && isFinite(r.pointA) && isFinite(r.pointB));
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-12);
}

// Same contact after moving both bodies by `motion` (depth and distance
// unchanged; normal rotated; points moved).
inline void expectSameUnderMotion(const ContactResult& reference, const ContactResult& moved, const Transform& motion,
                                  double tolerance, bool comparePoints = true) {
  expectFinite(moved);
  EXPECT_EQ(reference.status, moved.status);
  EXPECT_NEAR(reference.depth, moved.depth, tolerance);
  EXPECT_NEAR(reference.distance, moved.distance, tolerance);
  EXPECT_LE((motion.rotation * reference.normal - moved.normal).norm(), tolerance);
  if (comparePoints) {
    EXPECT_LE((motion.apply(reference.pointA) - moved.pointA).norm(), tolerance);
    EXPECT_LE((motion.apply(reference.pointB) - moved.pointB).norm(), tolerance);
  }
}

// Motions used for the invariance checks: identity, random rigid motions, and
// the same translated 1e3 and 1e5 away.
inline std::vector<Transform> testMotions(unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Transform> motions{Transform{}};
  for (double offset : {0.0, 1e3, 1e5}) {
    for (int i = 0; i < 3; ++i) {
      std::uniform_real_distribution<double> unit(-1.0, 1.0);
      const Vec3 shift = offset * Vec3(unit(rng), unit(rng), unit(rng)).normalized() + Vec3(unit(rng), unit(rng), unit(rng));
      motions.push_back({shift, randomRotation(rng)});
    }
  }
  return motions;
}

// Box pairs through GJK + EPA, as before the box-box SAT path existed: the
// reference the SAT path is checked against.
inline NarrowPhaseOptions gjkEpaOnly() {
  NarrowPhaseOptions options;
  options.boxBoxSat = false;
  return options;
}

}  // namespace physdbg::testing
