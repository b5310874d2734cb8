#pragma once
// Random box pairs and surface checks shared by the box-box narrow-phase and
// manifold tests.
#include <cmath>
#include <random>

#include "contact_test_helpers.h"
#include "engine/colliders/box_collider.h"

namespace physdbg::testing {

// Signed distance from `world` to the surface of a box: > 0 outside.
inline double boxSurfaceDistance(const Vec3& half, const Transform& transform, const Vec3& world) {
  const Vec3 excess = transform.applyInverse(world).cwiseAbs() - half;
  const double outside = excess.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : excess.maxCoeff();
}

struct BoxPair {
  Vec3 halfA, halfB;
  Transform ta, tb;
};

inline BoxPair randomBoxPair(std::mt19937& rng, double halfMin = 0.1, double halfMax = 1.5, double spread = 2.0) {
  std::uniform_real_distribution<double> half(halfMin, halfMax), position(-spread, spread);
  BoxPair pair;
  pair.halfA = Vec3(half(rng), half(rng), half(rng));
  pair.halfB = Vec3(half(rng), half(rng), half(rng));
  pair.ta = {Vec3(position(rng), position(rng), position(rng)), randomRotation(rng)};
  pair.tb = {Vec3(position(rng), position(rng), position(rng)), randomRotation(rng)};
  return pair;
}

}  // namespace physdbg::testing
