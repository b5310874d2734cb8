// scenes/jolt_pyramid.json is the scene joltPyramidScene() builds (the one
// `bench jolt_pyramid` runs): the same bodies in the same order, with the
// same shapes, masses, materials and settings; and it is Jolt's pyramid,
// 1240 boxes whose lowest layer rests on the floor.
#include <gtest/gtest.h>

#include "engine/colliders/box_collider.h"
#include "scenes/scene.h"
#include "scenes/stacking_scenes.h"

namespace physdbg {
namespace {

Vec3 halfExtents(const BodyDefinition& body) {
  return static_cast<const BoxCollider&>(*body.collider).halfExtents();
}

TEST(JoltPyramidScene, TheShippedFileIsTheBenchmarkScene) {
  const SceneDescription built = joltPyramidScene();
  const SceneDescription file = loadSceneFile(PHYSDBG_SOURCE_DIR "/scenes/jolt_pyramid.json");
  ASSERT_EQ(built.bodies.size(), 1241u);
  ASSERT_EQ(file.bodies.size(), built.bodies.size());
  EXPECT_EQ(file.steps, built.steps);
  EXPECT_EQ(file.world.allowSleep, built.world.allowSleep);
  EXPECT_FALSE(built.world.allowSleep);
  EXPECT_EQ(file.world.dt, built.world.dt);
  for (std::size_t i = 0; i < built.bodies.size(); ++i) {
    SCOPED_TRACE(i);
    const BodyDefinition &a = built.bodies[i], &b = file.bodies[i];
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.isStatic, b.isStatic);
    ASSERT_EQ(a.collider->kind(), ColliderKind::Box);
    ASSERT_EQ(b.collider->kind(), ColliderKind::Box);
    EXPECT_EQ(halfExtents(a), halfExtents(b));
    if (!a.isStatic) {
      EXPECT_EQ(a.mass, b.mass);
    }
    EXPECT_EQ(a.material.staticFriction, b.material.staticFriction);
    EXPECT_EQ(a.material.dynamicFriction, b.material.dynamicFriction);
    EXPECT_EQ(a.material.restitution, b.material.restitution);
  }
  int onFloor = 0;
  for (const BodyDefinition& body : built.bodies) onFloor += !body.isStatic && body.position.y() == 1.0 ? 1 : 0;
  EXPECT_EQ(onFloor, 15 * 15);
}

}  // namespace
}  // namespace physdbg
