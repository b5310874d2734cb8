// Sleeping bodies cost nothing: a step visits the awake bodies and their
// contacts only. A world whose dynamic bodies all sleep steps without
// changing a byte of any body, pair or contact; sleepers far away leave an
// awake scene bit for bit as it is alone; and the contacts a pile fell
// asleep with stay touching, silently, until it wakes.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

using testbodies::ball;
using testbodies::box;
using testbodies::floorSlab;

std::vector<unsigned char> bodyBytes(const World& world) {
  std::vector<unsigned char> bytes(world.bodyCount() * sizeof(RigidBody));
  for (std::size_t i = 0; i < world.bodyCount(); ++i)
    std::memcpy(bytes.data() + i * sizeof(RigidBody), static_cast<const void*>(&world.bodies()[i]), sizeof(RigidBody));
  return bytes;
}

class CountingListener : public ContactListener {
 public:
  void onContactBegin(const Contact&) override { ++events; }
  void onContactStay(const Contact&) override { ++events; }
  void onContactEnd(std::uint32_t, std::uint32_t) override { ++events; }
  int events = 0;
};

// Two stacks that fell asleep on their own (their contacts are dormant) and
// a row of boxes put to sleep before the first step. (Sequential impulses:
// the design's seed response never lets a stack rest.)
World sleepingWorld() {
  World world;
  world.addBody(floorSlab());
  for (int stack = 0; stack < 2; ++stack)
    for (int level = 0; level < 3; ++level) world.addBody(box(Vec3(-4.0 + 3.0 * stack, 0.5 + level, 0)));
  for (int i = 0; i < 5; ++i) world.sleep(world.addBody(box(Vec3(-4.0 + 2.0 * i, 0.5, 4))));
  return world;
}

TEST(SleepingCost, AStepWithOnlySleepersTouchesNoBodyState) {
  World world = sleepingWorld();
  CountingListener listener;
  world.setContactListener(&listener);
  for (int step = 0; step < 600 && (step == 0 || world.lastStepStats().awakeBodies > 0); ++step) world.step();
  ASSERT_EQ(world.lastStepStats().awakeBodies, 0) << "the stacks should have fallen asleep";
  ASSERT_EQ(world.lastStepStats().sleepingBodies, 11);
  const std::vector<BodyPair> touching = world.candidatePairs();
  const std::vector<unsigned char> before = bodyBytes(world);
  const int eventsBefore = listener.events;
  for (int step = 0; step < 50; ++step) {
    world.step();
    const StepStats& stats = world.lastStepStats();
    EXPECT_EQ(stats.awakeBodies, 0);
    EXPECT_EQ(stats.sleepingBodies, 11);
    EXPECT_EQ(stats.candidatePairs, 0);
    EXPECT_EQ(stats.contacts, 0);
    EXPECT_EQ(stats.manifolds, 0);
  }
  EXPECT_EQ(bodyBytes(world), before) << "a step changed a sleeping or static body";
  EXPECT_EQ(listener.events, eventsBefore) << "sleeping contacts neither stay, end nor begin";
  EXPECT_TRUE(touching.empty());
  // Dormant, not gone: the stacks' contacts still show as resting points.
  int resting = 0;
  for (const ShownContact& point : world.shownContacts()) resting += point.resting ? 1 : 0;
  EXPECT_GE(resting, 6 * 4) << "each stacked box rests on four points at least";
}

// The ball lands beside 2000 sleeping boxes 100 m away as it lands alone,
// bit for bit: nothing of the sleepers enters its step.
class SleepersFarAway : public ::testing::TestWithParam<SolverKind> {};

TEST_P(SleepersFarAway, LeaveAnAwakeSceneAsItIsAlone) {
  const auto run = [&](int sleepers) {
    WorldSettings settings;
    settings.solver.kind = GetParam();
    World world(settings);
    world.addBody(floorSlab());
    const BodyId falling = world.addBody(ball(Vec3(0.1, 3, 0)));
    for (int i = 0; i < sleepers; ++i) {
      BodyDefinition prop = box(Vec3(100.0 + 1.5 * (i % 50), 0.5, 1.5 * (i / 50)));
      world.sleep(world.addBody(prop));
    }
    world.body(falling).setAngularVelocity(Vec3(0, 0, 2));
    std::vector<Vec3> path;
    for (int step = 0; step < 120; ++step) {
      world.step();
      path.push_back(world.body(falling).position());
      EXPECT_EQ(world.lastStepStats().sleepingBodies, sleepers);
    }
    return path;
  };
  EXPECT_EQ(run(0), run(2000));
}

// A wake reaches the whole island it fell asleep with, and only it.
TEST(SleepingCost, AWakeVisitsItsIslandOnly) {
  World world = sleepingWorld();
  for (int step = 0; step < 600; ++step) world.step();
  ASSERT_EQ(world.lastStepStats().awakeBodies, 0);
  world.wake(2);  // the first stack's middle box
  world.step();
  for (BodyId id = 1; id <= 3; ++id) EXPECT_FALSE(world.isAsleep(id)) << id;
  for (BodyId id = 4; id < world.bodyCount(); ++id) EXPECT_TRUE(world.isAsleep(id)) << id;
}

INSTANTIATE_TEST_SUITE_P(Solvers, SleepersFarAway,
                         ::testing::Values(SolverKind::SequentialImpulse, SolverKind::Seed),
                         [](const ::testing::TestParamInfo<SolverKind>& info) {
                           return info.param == SolverKind::Seed ? std::string("Seed") : std::string("SequentialImpulse");
                         });

}  // namespace
}  // namespace physdbg
