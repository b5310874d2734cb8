#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "bench/bullet_world.h"
#include "bench/drop_scene.h"
#include "bench/side_by_side.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/triangle_collider.h"

namespace physdbg::bench {
namespace {

// NOTES.md: footprint ceil(sqrt(N/4)) cells of 1.2 m, first layer at y = 1.
TEST(DropScene, GridFollowsTheSpecification) {
  const DropScene drop = dropScene(1000, DropShape::Sphere, false);
  ASSERT_EQ(drop.scene.bodies.size(), 1005u);
  EXPECT_DOUBLE_EQ(drop.container.innerHalfWidth, 0.5 * 16 * 1.2);
  double lowest = 1e9, highest = -1e9;
  for (std::size_t i = drop.firstDropped; i < drop.scene.bodies.size(); ++i) {
    const Vec3& p = drop.scene.bodies[i].position;
    lowest = std::min(lowest, p.y());
    highest = std::max(highest, p.y());
    EXPECT_FALSE(leftContainer(p, drop.container)) << i;
  }
  EXPECT_DOUBLE_EQ(lowest, 1.0);
  EXPECT_DOUBLE_EQ(highest, 1.0 + 3 * 1.2);  // 1000 bodies on 16 x 16 cells: 4 layers
  EXPECT_LT(highest + 0.5, drop.container.wallTop);
  EXPECT_FALSE(drop.scene.world.allowSleep);
}

// The jitter is the documented formula: splitmix64's first output for state
// k (0xe220a8397b1dcdaf for k = 0), as a number in [-1, 1); each body moves
// sideways by at most 5 cm, never up or down, the same every time.
TEST(DropScene, JitterIsTheDocumentedFormula) {
  EXPECT_EQ(dropJitter(0), 2.0 * static_cast<double>(0xe220a8397b1dcdafULL >> 11) * 0x1.0p-53 - 1.0);
  const DropScene columns = dropScene(1000, DropShape::Sphere, false);
  const DropScene jittered = dropScene(1000, DropShape::Sphere);
  ASSERT_EQ(jittered.scene.bodies.size(), columns.scene.bodies.size());
  double largest = 0.0, sumX = 0.0;
  for (std::size_t i = jittered.firstDropped; i < jittered.scene.bodies.size(); ++i) {
    const Vec3 offset = jittered.scene.bodies[i].position - columns.scene.bodies[i].position;
    const auto k = static_cast<std::uint64_t>(i - jittered.firstDropped);
    EXPECT_EQ(offset.y(), 0.0);
    EXPECT_NEAR(offset.x(), 0.05 * dropJitter(2 * k), 1e-12) << i;  // the subtraction rounds at 10 m
    EXPECT_NEAR(offset.z(), 0.05 * dropJitter(2 * k + 1), 1e-12) << i;
    largest = std::max(largest, offset.cwiseAbs().maxCoeff());
    sumX += offset.x();
  }
  EXPECT_LE(largest, 0.05);
  EXPECT_GT(largest, 0.04);  // the offsets span their range
  EXPECT_LT(std::abs(sumX) / 1000.0, 0.005);  // and centre on zero
  for (std::size_t i = 0; i < jittered.scene.bodies.size(); ++i)
    EXPECT_EQ(dropScene(1000, DropShape::Sphere).scene.bodies[i].position, jittered.scene.bodies[i].position);
}

TEST(DropScene, LeavingTheContainerIsDetected) {
  const DropScene drop = dropScene(16, DropShape::Box);
  EXPECT_TRUE(leftContainer(Vec3(drop.container.innerHalfWidth + 0.5, 1, 0), drop.container));
  EXPECT_TRUE(leftContainer(Vec3(0, -1, 0), drop.container));
  EXPECT_THROW(dropScene(0, DropShape::Box), std::invalid_argument);
}

// The same scene in both engines: in free fall (before anything touches)
// both integrators give exact velocities, so kinetic energy agrees to
// Bullet's single precision. (Positions differ by the integrators' O(dt)
// terms: ours substeps.)
TEST(BulletWorld, FreeFallMatchesOurs) {
  if (!BulletWorld::available()) GTEST_SKIP() << "built without Bullet";
  const DropScene drop = dropScene(64, DropShape::Box);
  const EngineRun ours = runOurs(drop.scene, 10, {}, 1);
  const EngineRun peer = runBullet(drop.scene, 10, false);
  ASSERT_GT(ours.kineticEnergy, 0.0);
  EXPECT_NEAR(peer.kineticEnergy / ours.kineticEnergy, 1.0, 1e-5);
  EXPECT_EQ(peer.finalPositions.size(), ours.finalPositions.size());
}

TEST(BulletWorld, RejectsShapesItCannotBuild) {
  if (!BulletWorld::available()) GTEST_SKIP() << "built without Bullet";
  SceneDescription scene;
  BodyDefinition triangle;  // a mesh's triangle on its own: only the narrow phase makes one
  triangle.collider = std::make_shared<TriangleCollider>(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3::UnitY());
  triangle.isStatic = true;
  scene.bodies.push_back(triangle);
  EXPECT_THROW(BulletWorld(scene, true), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::bench
