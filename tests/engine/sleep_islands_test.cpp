// Islands sleep and wake as a whole (SleepIslands::findSleepers, World::wake). The
// old rule vetoed sleep one contact at a time, so a body two contacts away
// from a moving one could fall asleep and be woken on the next step. These
// worlds keep one body moving forever (a frictionless sphere spinning in
// place) and check every step that nothing linked to it sleeps.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

using testbodies::box;
using testbodies::floorSlab;

constexpr Material frictionless{0.0, 0.0, 0.0};

// Spins about the vertical axis on frictionless contacts: it stays where it
// is and never slows down, so it is never slow enough to sleep.
BodyDefinition spinningSphere(const Vec3& position) {
  BodyDefinition body;
  body.collider = std::make_shared<SphereCollider>(0.5);
  body.position = position;
  body.angularVelocity = Vec3(0, 5, 0);
  body.material = frictionless;
  return body;
}

// Unit boxes one on another from the floor up, a floor slab below them.
std::vector<BodyId> addStackOnFloor(World& world, int levels) {
  world.addBody(floorSlab());
  std::vector<BodyId> stack;
  for (int level = 0; level < levels; ++level) stack.push_back(world.addBody(box(Vec3(0, 0.5 + level, 0))));
  return stack;
}

WorldSettings settingsFor(SolverKind kind) {
  WorldSettings settings;
  settings.solver.kind = kind;
  return settings;
}

int stepsFor(const World& world, double seconds) { return static_cast<int>(seconds / world.settings().dt); }

bool anyAsleep(const World& world, const std::vector<BodyId>& bodies) {
  for (BodyId id : bodies)
    if (world.isAsleep(id)) return true;
  return false;
}

bool allAsleep(const World& world, const std::vector<BodyId>& bodies) {
  for (BodyId id : bodies)
    if (!world.isAsleep(id)) return false;
  return true;
}

class SleepIslands : public ::testing::TestWithParam<SolverKind> {};

// Floor, box 1 on it, box 2 on box 1, the spinning sphere on box 2. Box 1
// touches only slow bodies, yet its island holds the sphere.
TEST_P(SleepIslands, ChainNeverSleepsWhileItsSphereSpins) {
  World world(settingsFor(GetParam()));
  world.addBody(floorSlab());
  const BodyId lower = world.addBody(box(Vec3(0, 0.5, 0)));
  const BodyId upper = world.addBody(box(Vec3(0, 1.5, 0)));
  const BodyId sphere = world.addBody(spinningSphere(Vec3(0, 2.5, 0)));
  const std::vector<BodyId> chain{lower, upper, sphere};
  for (int step = 0; step < stepsFor(world, 4.0); ++step) {
    world.step();
    ASSERT_FALSE(anyAsleep(world, chain)) << "step " << step;
    ASSERT_EQ(world.islandOf(lower), world.islandOf(sphere)) << "step " << step;
  }
}

// A three-box stack beside a pile (a box with the spinning sphere on it)
// whose box touches the stack's bottom box: one island, kept awake.
TEST_P(SleepIslands, StackTouchingAnAwakePileStaysAwake) {
  World world(settingsFor(GetParam()));
  const std::vector<BodyId> stack = addStackOnFloor(world, 3);
  const BodyId pileBox = world.addBody(box(Vec3(1.0, 0.5, 0)));
  const BodyId sphere = world.addBody(spinningSphere(Vec3(1.0, 1.5, 0)));
  for (int step = 0; step < stepsFor(world, 4.0); ++step) {
    world.step();
    ASSERT_EQ(world.islandOf(stack[0]), world.islandOf(pileBox)) << "step " << step;
    ASSERT_FALSE(anyAsleep(world, stack)) << "step " << step;
    ASSERT_FALSE(world.isAsleep(sphere)) << "step " << step;
  }
}

// Without anything moving, the stack falls asleep, all of it on one step.
TEST_P(SleepIslands, RestingStackFallsAsleepAllAtOnce) {
  World world(settingsFor(GetParam()));
  const std::vector<BodyId> stack = addStackOnFloor(world, 4);
  bool asleep = false;
  for (int step = 0; step < stepsFor(world, 5.0) && !asleep; ++step) {
    world.step();
    asleep = anyAsleep(world, stack);
    if (asleep) {
      EXPECT_TRUE(allAsleep(world, stack)) << "part of the stack fell asleep at step " << step;
    }
  }
  EXPECT_TRUE(asleep);
}

// Waking one body of a sleeping island wakes every body of it, and only it.
TEST_P(SleepIslands, WakingOneBodyWakesItsIsland) {
  World world(settingsFor(GetParam()));
  const std::vector<BodyId> stack = addStackOnFloor(world, 3);
  const BodyId apart = world.addBody(box(Vec3(4, 0.5, 0)));
  for (int step = 0; step < stepsFor(world, 5.0) && !(allAsleep(world, stack) && world.isAsleep(apart)); ++step)
    world.step();
  ASSERT_TRUE(allAsleep(world, stack));
  ASSERT_TRUE(world.isAsleep(apart));
  EXPECT_NE(world.islandOf(stack[0]), world.islandOf(apart));
  world.wake(stack[2]);
  EXPECT_FALSE(anyAsleep(world, stack));
  EXPECT_TRUE(world.isAsleep(apart));
  world.step();
  EXPECT_FALSE(anyAsleep(world, stack));
}

// A push (not a wake call) on the middle box wakes the bodies below it too.
TEST_P(SleepIslands, PushingOneBodyWakesItsIsland) {
  World world(settingsFor(GetParam()));
  const std::vector<BodyId> stack = addStackOnFloor(world, 3);
  for (int step = 0; step < stepsFor(world, 5.0) && !allAsleep(world, stack); ++step) world.step();
  ASSERT_TRUE(allAsleep(world, stack));
  world.body(stack[1]).addForce(Vec3(0, 0.1, 0), ForceMode::Impulse);
  world.step();
  EXPECT_FALSE(anyAsleep(world, stack));
  EXPECT_EQ(world.lastStepStats().awakeBodies, 3);
}

// The sequential-impulse solver (the default) holds stacks still enough to
// sleep; the seed solver's one-point response keeps boxes rocking.
INSTANTIATE_TEST_SUITE_P(SequentialImpulse, SleepIslands, ::testing::Values(SolverKind::SequentialImpulse));

}  // namespace
}  // namespace physdbg
