// Kinematic bodies: moved by their velocities alone, infinite mass in
// contacts, never asleep, waking what they touch, their tree box following.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/colliders/box_collider.h"
#include "engine/world.h"

namespace physdbg {
namespace {

BodyDefinition boxBody(const Vec3& halfExtents, const Vec3& position) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(halfExtents);
  body.position = position;
  body.material.staticFriction = body.material.dynamicFriction = 0.0;
  return body;
}

struct Pusher {
  World world;
  BodyId floor, pusher, pushed;
};

// A frictionless floor, a kinematic unit box at 1 m/s along x, and a 1 kg
// unit box at rest 0.5 m ahead of it.
Pusher pusherScene(SolverKind solver) {
  WorldSettings settings;
  settings.solver.kind = solver;
  Pusher scene{World(settings), 0, 0, 0};
  BodyDefinition floor = boxBody(Vec3(50, 0.5, 5), Vec3(0, -0.5, 0));
  floor.isStatic = true;
  scene.floor = scene.world.addBody(floor);
  BodyDefinition pusher = boxBody(Vec3(0.5, 0.5, 0.5), Vec3(0, 0.5, 0));
  pusher.isKinematic = true;
  pusher.linearVelocity = Vec3(1, 0, 0);
  scene.pusher = scene.world.addBody(pusher);
  scene.pushed = scene.world.addBody(boxBody(Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.5, 0)));
  return scene;
}

// The kinematic box keeps exactly its velocity and its path x = t; the one
// it pushes is never overlapped by more than the slop, and ends moving with it.
TEST(KinematicBody, PushesADynamicBoxAndKeepsItsPath) {
  Pusher scene = pusherScene(SolverKind::SequentialImpulse);
  World& world = scene.world;
  const double slop = world.settings().solver.linearSlop;
  double deepest = 0.0;
  for (int step = 1; step <= 180; ++step) {
    world.step();
    const RigidBody& pusher = world.body(scene.pusher);
    ASSERT_EQ(pusher.linearVelocity(), Vec3(1, 0, 0));
    ASSERT_EQ(pusher.angularVelocity(), Vec3::Zero());
    ASSERT_NEAR(pusher.position().x(), step * world.settings().dt, 1e-12);
    ASSERT_EQ(pusher.position().y(), 0.5);
    const double overlap = 1.0 - (world.body(scene.pushed).position().x() - pusher.position().x());
    deepest = std::max(deepest, overlap);
  }
  EXPECT_LE(deepest, slop);
  EXPECT_NEAR(world.body(scene.pushed).linearVelocity().x(), 1.0, 1e-3);
  EXPECT_FALSE(world.isAsleep(scene.pusher));
}

// The design's solver pushes too (one point, position correction), and the
// kinematic box is still unmoved by the contact.
TEST(KinematicBody, SeedSolverTreatsItAsInfinitelyHeavy) {
  Pusher scene = pusherScene(SolverKind::Seed);
  for (int step = 1; step <= 120; ++step) {
    scene.world.step();
    ASSERT_EQ(scene.world.body(scene.pusher).linearVelocity(), Vec3(1, 0, 0));
  }
  EXPECT_GT(scene.world.body(scene.pushed).position().x(), 2.0);
  EXPECT_GT(scene.world.body(scene.pushed).position().x() - scene.world.body(scene.pusher).position().x(), 0.9);
}

TEST(KinematicBody, IgnoresGravityAndForcesAndItsTreeBoxFollows) {
  World world;
  BodyDefinition body = boxBody(Vec3(0.5, 0.5, 0.5), Vec3(0, 5, 0));
  body.isKinematic = true;
  body.angularVelocity = Vec3(0, 1, 0);
  const BodyId id = world.addBody(body);
  world.body(id).addForce(Vec3(100, 0, 0));
  EXPECT_THROW(world.scheduleForce({id, Vec3(1, 0, 0)}), std::invalid_argument);
  world.body(id).setLinearVelocity(Vec3(0, 0, 2));
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_NEAR(world.body(id).position().z(), 2.0, 1e-12);
  EXPECT_EQ(world.body(id).position().y(), 5.0);
  EXPECT_EQ(world.body(id).position().x(), 0.0);
  EXPECT_NEAR(world.body(id).orientation().angularDistance(Quat(Eigen::AngleAxisd(1.0, Vec3::UnitY()))), 0.0, 1e-9);
  ASSERT_NE(world.tree(), nullptr);
  const Aabb tight = world.body(id).collider().worldBounds(world.body(id).transform());
  bool covered = false;
  world.tree()->query(tight, [&](int proxy) {
    covered = covered || (world.tree()->userData(proxy) == id && world.tree()->fatBox(proxy).contains(tight));
    return true;
  });
  EXPECT_TRUE(covered);
}

TEST(KinematicBody, WakesASleepingBodyItReaches) {
  WorldSettings settings;
  World world(settings);
  BodyDefinition floor = boxBody(Vec3(50, 0.5, 5), Vec3(0, -0.5, 0));
  floor.isStatic = true;
  world.addBody(floor);
  const BodyId resting = world.addBody(boxBody(Vec3(0.5, 0.5, 0.5), Vec3(3, 0.5, 0)));
  BodyDefinition pusher = boxBody(Vec3(0.5, 0.5, 0.5), Vec3(0, 0.5, 0));
  pusher.isKinematic = true;
  const BodyId kinematic = world.addBody(pusher);
  for (int i = 0; i < 60 && !world.isAsleep(resting); ++i) world.step();
  ASSERT_TRUE(world.isAsleep(resting));
  world.body(kinematic).setLinearVelocity(Vec3(2, 0, 0));
  for (int i = 0; i < 90; ++i) world.step();
  EXPECT_FALSE(world.isAsleep(resting));
  EXPECT_GT(world.body(resting).position().x(), 3.5);
}

TEST(KinematicBody, CannotAlsoBeStatic) {
  BodyDefinition body = boxBody(Vec3(1, 1, 1), Vec3::Zero());
  body.isStatic = body.isKinematic = true;
  World world;
  EXPECT_THROW(world.addBody(body), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg
