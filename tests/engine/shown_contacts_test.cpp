// The contacts the debugger shows (World::shownContacts): frame 0's without a
// step, every step's since the last frame, and those sleeping bodies rest on;
// none of it changes the simulation.
#include <gtest/gtest.h>

#include <set>

#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

std::set<BodyPair> pairsOf(const std::vector<ShownContact>& points) {
  std::set<BodyPair> pairs;
  for (const ShownContact& point : points) pairs.insert(point.pair);
  return pairs;
}

TEST(ShownContacts, FrameZeroShowsTheInitialTouchingPairsWithoutStepping) {
  World world = buildWorld(resolveScene("stack"));
  const std::vector<ShownContact> shown = world.shownContacts();
  EXPECT_EQ(contactPairCount(shown), 10);  // `physdbg contacts stack`: floor-box and nine box-box pairs
  EXPECT_EQ(world.stepCount(), 0);
  EXPECT_EQ(world.candidatePairs().size(), 0u);
}

TEST(ShownContacts, LookingChangesNoState) {
  World looked = buildWorld(resolveScene("stack"));
  World untouched = buildWorld(resolveScene("stack"));
  looked.keepContactHistory(true);
  for (int step = 0; step < 120; ++step) {
    (void)looked.shownContacts();
    looked.step();
    untouched.step();
    if (step % 7 == 0) looked.clearContactHistory();
  }
  for (BodyId id = 0; id < looked.bodyCount(); ++id) {
    EXPECT_EQ(looked.body(id).position(), untouched.body(id).position()) << "body " << id;
    EXPECT_EQ(looked.body(id).linearVelocity(), untouched.body(id).linearVelocity()) << "body " << id;
  }
}

// Between two looks the history holds every ball's impact, though at the
// end of the interval the bouncier balls are back in the air.
TEST(ShownContacts, HistoryKeepsEveryImpactSinceTheLastLook) {
  World world = buildWorld(resolveScene("bounce"));
  world.keepContactHistory(true);
  for (int step = 0; step < 70; ++step) world.step();
  const std::set<BodyPair> pairs = pairsOf(world.shownContacts());
  for (std::uint32_t ball = 1; ball <= 4; ++ball) EXPECT_TRUE(pairs.count({0, ball})) << "ball " << ball;
  world.clearContactHistory();
  world.step();
  EXPECT_LT(pairsOf(world.shownContacts()).size(), 4u);  // a look starts over
}

// 300 steps held in one history cost what a few steps do: a point per pair
// and feature (feature ids change while a box settles, then repeat).
TEST(ShownContacts, HistoryKeepsOnePointPerPairAndFeature) {
  World world = buildWorld(resolveScene("stack"));
  world.keepContactHistory(true);
  world.step();
  const std::size_t afterOne = world.shownContacts().size();
  for (int step = 0; step < 300; ++step) world.step();
  const std::vector<ShownContact> shown = world.shownContacts();
  EXPECT_LE(shown.size(), 4 * afterOne);
  for (std::size_t i = 1; i < shown.size(); ++i)
    EXPECT_FALSE(shown[i].pair == shown[i - 1].pair && shown[i].feature == shown[i - 1].feature) << i;
}

TEST(ShownContacts, ASleepingStackStillShowsWhatItRestsOn) {
  World world = buildWorld(resolveScene("stack"));
  int step = 0;
  while (!world.isAsleep(10) && step < 600) world.step(), ++step;
  ASSERT_TRUE(world.isAsleep(10)) << "the stack never fell asleep";
  world.step();
  const std::vector<ShownContact> shown = world.shownContacts();
  EXPECT_EQ(contactPairCount(shown), 10);
  for (const ShownContact& point : shown) EXPECT_TRUE(point.resting);
}

}  // namespace
}  // namespace physdbg

namespace physdbg {
namespace {

// The sleep layer outlines a sleeping pile as one island around all its
// boxes, besides marking each sleeping body (the floor links nothing).
TEST(ShownContacts, TheSleepLayerOutlinesASleepingStackAsOneIsland) {
  World world = buildWorld(resolveScene("stack"));
  for (int step = 0; step < 600 && !world.isAsleep(10); ++step) world.step();
  ASSERT_TRUE(world.isAsleep(10));
  debugdraw::Frame frame;
  emitDebugDraw(world, debugdraw::parseLayers("sleep"), frame);
  ASSERT_EQ(frame.wireBoxes.size(), 11u);  // ten sleeping boxes, then the island
  const debugdraw::WireBox& island = frame.wireBoxes.back();
  for (BodyId id = 1; id <= 10; ++id) {
    const Aabb box = world.body(id).collider().worldBounds(world.body(id).transform());
    EXPECT_TRUE((box.min.array() >= (island.center - island.halfExtents).array()).all()) << id;
    EXPECT_TRUE((box.max.array() <= (island.center + island.halfExtents).array()).all()) << id;
  }
}

}  // namespace
}  // namespace physdbg
