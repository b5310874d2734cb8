#include <cmath>
#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "bench/bullet_world.h"
#include "bench/drop_scene.h"
#include "bench/side_by_side.h"
#include "engine/colliders/capsule_collider.h"

namespace physdbg::bench {
namespace {

// NOTES.md: footprint ceil(sqrt(N/4)) cells of 1.2 m, first layer at y = 1.
TEST(DropScene, GridFollowsTheSpecification) {
  const DropScene drop = dropScene(1000, DropShape::Sphere);
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
  BodyDefinition capsule;
  capsule.collider = std::make_shared<CapsuleCollider>(0.5, 0.25);
  scene.bodies.push_back(capsule);
  EXPECT_THROW(BulletWorld(scene, true), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::bench
