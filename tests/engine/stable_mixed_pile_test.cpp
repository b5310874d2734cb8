// Property test: piles of mixed shapes (boxes, spheres, capsules, random
// hulls) with masses spread over three decades (0.1 to 100 kg), dropped into
// a walled container. Fixed seeds. Whatever the mix: no numerical fault, no
// body through the floor or out of the container, and once the pile has
// settled no contact between settled bodies overlaps by 1 cm or more. A pile
// may still be rearranging after 4 s (bodies tumbling off it at 1 m/s in
// about one seed in six): their impacts are reported, not judged here.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"
#include "scenes/body_builders.h"
#include "stable_test_helpers.h"

namespace physdbg {
namespace {

constexpr double containerHalfWidth = 4.0;

std::shared_ptr<const Collider> randomShape(std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = 0.2 + 0.3 * unit(random);
  switch (random() % 4) {
    case 0:
      return std::make_shared<BoxCollider>(Vec3(size, 0.2 + 0.3 * unit(random), size));
    case 1:
      return std::make_shared<SphereCollider>(size);
    case 2:
      return std::make_shared<CapsuleCollider>(0.5 * size, size);
    default: {
      std::vector<Vec3> points;
      for (int i = 0; i < 12; ++i) points.push_back(2.0 * size * Vec3(unit(random), unit(random), unit(random)));
      return std::make_shared<ConvexMeshCollider>(points);
    }
  }
}

World mixedPile(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  WorldSettings settings;
  settings.allowSleep = false;
  World world(settings);
  const double wall = containerHalfWidth + 0.5;
  world.addBody(staticBox(Vec3(0, -0.5, 0), Vec3(wall + 0.5, 0.5, wall + 0.5)));
  for (double side : {-wall, wall}) {
    world.addBody(staticBox(Vec3(side, 4, 0), Vec3(0.5, 4, wall)));
    world.addBody(staticBox(Vec3(0, 4, side), Vec3(wall, 4, 0.5)));
  }
  for (int layer = 0; layer < 3; ++layer)
    for (int x = -2; x <= 2; ++x)
      for (int z = -2; z <= 2; ++z) {
        const double mass = std::pow(10.0, -1.0 + 3.0 * unit(random));
        const Vec3 position(1.4 * x + 0.1 * unit(random), 1.0 + 1.4 * layer, 1.4 * z + 0.1 * unit(random));
        world.addBody(dynamicBody(randomShape(random), position, mass));
      }
  return world;
}

class MixedPile : public ::testing::TestWithParam<unsigned> {};

// Slower than 0.1 m/s and 0.2 rad/s (a rim speed of 0.1 m/s on the largest
// bodies), or static.
bool settled(const RigidBody& body) {
  return body.isStatic() || (body.linearVelocity().norm() < 0.1 && body.angularVelocity().norm() < 0.2);
}

// The deepest overlap, after the step, of the last step's contacts between
// two settled bodies.
double deepestSettledOverlap(const World& world) {
  double deepest = 0.0;
  for (const ContactManifold& manifold : world.manifolds()) {
    const RigidBody &a = world.body(manifold.a), &b = world.body(manifold.b);
    if (!settled(a) || !settled(b)) continue;
    for (int p = 0; p < manifold.pointCount; ++p) {
      const ManifoldPoint& point = manifold.points[p];
      const double gap = manifold.normal.dot(b.transform().apply(point.localB) - a.transform().apply(point.localA));
      deepest = std::max(deepest, -gap);
    }
  }
  return deepest;
}

TEST_P(MixedPile, SettlesWithoutFaultsEscapesOrDeepOverlap) {
  World world = mixedPile(GetParam());
  double settledOverlap = 0.0, anyOverlap = 0.0;
  int mostSubsteps = 0;
  for (int i = 0; i < 480; ++i) {
    world.step();
    mostSubsteps = std::max(mostSubsteps, world.lastStepStats().substeps);
    if (i < 240) continue;
    anyOverlap = std::max(anyOverlap, world.lastStepStats().largestPenetration);
    settledOverlap = std::max(settledOverlap, deepestSettledOverlap(world));
  }
  stable::reportFigure("deepest overlap after 4 s, settled bodies (m)", settledOverlap);
  stable::reportFigure("deepest overlap after 4 s, any contact (m)", anyOverlap);
  stable::reportFigure("most substeps", mostSubsteps);
  EXPECT_TRUE(world.numericalFaults().empty());
  EXPECT_LT(settledOverlap, 0.01);
  EXPECT_LE(mostSubsteps, world.settings().solver.maxSubsteps);
  for (const RigidBody& body : world.bodies()) {
    if (body.isStatic()) continue;
    EXPECT_GT(body.position().y(), 0.0) << "through the floor";
    EXPECT_LT(std::max(std::abs(body.position().x()), std::abs(body.position().z())), containerHalfWidth)
        << "out of the container";
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, MixedPile, ::testing::Values(1u, 2u, 3u));

}  // namespace
}  // namespace physdbg
