// Bodies added and removed during a run (World::scheduleLifetime,
// removeBody, restoreBody): absent bodies take no part in anything, their
// pairs end with `end` events, what rested on them falls, and the broad-phase
// tree stays valid and keeps its rotation rules on removal.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

using testbodies::ball;
using testbodies::box;
using testbodies::floorSlab;

struct EndEvent {
  std::uint32_t a, b;
  int step;  // the step (1-based) that fired it
};

class EndListener final : public ContactListener {
 public:
  explicit EndListener(const World& world) : world_(world) {}
  void onContactBegin(const Contact&) override {}
  void onContactStay(const Contact&) override {}
  void onContactEnd(std::uint32_t a, std::uint32_t b) override { ends.push_back({a, b, world_.stepCount() + 1}); }
  std::vector<EndEvent> ends;

 private:
  const World& world_;
};

class BodyLifetimeTest : public ::testing::TestWithParam<SolverKind> {
 protected:
  WorldSettings settings() const {
    WorldSettings result;
    result.solver.kind = GetParam();
    return result;
  }
};

// Absent until state 30: gravity does not touch it, the tree does not hold
// it. From state 30 it falls from where it was placed exactly as the same
// ball dropped at step 0 in a world of its own, bit for bit.
TEST_P(BodyLifetimeTest, AddedBodyWaitsThenFallsFromItsPlace) {
  World world(settings());
  const BodyId late = world.addBody(ball(Vec3(0, 10, 0)));
  world.scheduleLifetime({late, 30, std::nullopt});
  for (int step = 0; step < 30; ++step) {
    ASSERT_FALSE(world.isPresent(late)) << "state " << step;
    world.step();
  }
  ASSERT_TRUE(world.isPresent(late));
  EXPECT_EQ(world.body(late).position(), Vec3(0, 10, 0));
  EXPECT_EQ(world.body(late).linearVelocity(), Vec3::Zero());
  ASSERT_NE(world.tree(), nullptr);
  EXPECT_EQ(world.tree()->proxyCount(), 1);
  World reference(settings());
  const BodyId dropped = reference.addBody(ball(Vec3(0, 10, 0)));
  for (int k = 1; k <= 20; ++k) {
    world.step();
    reference.step();
    EXPECT_EQ(world.body(late).position(), reference.body(dropped).position()) << "k " << k;
  }
  EXPECT_LT(world.body(late).position().y(), 9.6);  // fell g t^2 / 2 = 0.55 m in 1/3 s
}

// The middle box of three is removed at state 120, after the stack fell
// asleep: its two pairs end at once, the top box wakes and falls onto the
// bottom one (a drop of 1 m), and the tree is valid with one leaf fewer.
// Sequential impulses only: under the design's response a stack of three
// never comes to rest, so which pairs touch at step 120 is not fixed.
TEST(BodyLifetime, RemovingASupportEndsItsPairsAndDropsWhatItHeld) {
  World world;
  EndListener listener(world);
  world.setContactListener(&listener);
  const BodyId floor = world.addBody(floorSlab());
  const BodyId bottom = world.addBody(box(Vec3(0, 0.5, 0)));
  const BodyId middle = world.addBody(box(Vec3(0, 1.5, 0)));
  const BodyId top = world.addBody(box(Vec3(0, 2.5, 0)));
  world.scheduleLifetime({middle, 0, 120});
  for (int step = 0; step < 119; ++step) world.step();
  ASSERT_TRUE(world.isAsleep(top)) << "the stack should sleep before the removal";
  ASSERT_TRUE(listener.ends.empty());
  world.step();  // reaches state 120: the middle box leaves
  EXPECT_FALSE(world.isPresent(middle));
  ASSERT_EQ(listener.ends.size(), 2u);
  for (const EndEvent& end : listener.ends) {
    EXPECT_EQ(end.step, 120) << "the step that ends in state 120";
    EXPECT_TRUE(end.a == middle || end.b == middle);
  }
  EXPECT_FALSE(world.isAsleep(top)) << "what rested on the removed box must wake";
  EXPECT_EQ(world.tree()->validate(), "");
  EXPECT_EQ(world.tree()->proxyCount(), 3);
  const Vec3 middleAt = world.body(middle).position();
  for (int step = 0; step < 120; ++step) world.step();
  EXPECT_NEAR(world.body(top).position().y(), 1.5, 0.02) << "the top box lands on the bottom one";
  EXPECT_NEAR(world.body(bottom).position().y(), 0.5, 0.02);
  EXPECT_EQ(world.body(middle).position(), middleAt) << "nothing moves an absent body";
  EXPECT_TRUE(world.isPresent(floor));
}

// Removed and restored by hand: while out, nothing collides with it (a ball
// falls through where it was); back in, it is awake and in the tree again.
TEST_P(BodyLifetimeTest, RemovedBodyLetsOthersThroughUntilRestored) {
  World world(settings());
  BodyDefinition shelf = box(Vec3(0, 2, 0));
  shelf.isStatic = true;
  const BodyId shelfId = world.addBody(shelf);
  const BodyId falling = world.addBody(ball(Vec3(0, 4, 0)));
  world.removeBody(shelfId);
  for (int step = 0; step < 60; ++step) world.step();
  EXPECT_LT(world.body(falling).position().y(), 1.0) << "the ball fell through the absent shelf";
  world.restoreBody(shelfId);
  EXPECT_TRUE(world.isPresent(shelfId));
  EXPECT_EQ(world.tree()->proxyCount(), 2);
  EXPECT_EQ(world.tree()->validate(), "");
}

// Bodies absent at state 0 are not drawn, and are listed with the absent flag.
TEST_P(BodyLifetimeTest, AbsentBodiesDrawNothingAndAreMarked) {
  World world(settings());
  world.addBody(floorSlab());
  const BodyId late = world.addBody(box(Vec3(3, 0.5, 0)));
  world.scheduleLifetime({late, 5, std::nullopt});
  debugdraw::Frame frame;
  emitDebugDraw(world, debugdraw::parseLayers("shapes,aabbs,fat,velocities,contacts"), frame);
  for (const debugdraw::SolidBox& solid : frame.boxes) EXPECT_NE(solid.tag.body, static_cast<int>(late));
  for (const debugdraw::WireBox& wire : frame.wireBoxes) EXPECT_NE(wire.tag.body, static_cast<int>(late));
  emitBodies(world, frame);
  ASSERT_EQ(frame.bodies.size(), 2u);
  EXPECT_FALSE(frame.bodies[0].absent);
  EXPECT_TRUE(frame.bodies[1].absent);
  for (int step = 0; step < 5; ++step) world.step();
  debugdraw::Frame after;
  emitDebugDraw(world, debugdraw::parseLayers("shapes"), after);
  EXPECT_EQ(after.boxes.size(), 2u);
}

TEST_P(BodyLifetimeTest, BadLifetimesAreRefused) {
  World world(settings());
  const BodyId body = world.addBody(ball(Vec3::Zero()));
  EXPECT_THROW(world.scheduleLifetime({body + 1, 0, 5}), std::invalid_argument);
  EXPECT_THROW(world.scheduleLifetime({body, -1, 5}), std::invalid_argument);
  EXPECT_THROW(world.scheduleLifetime({body, 5, 5}), std::invalid_argument);
  world.scheduleLifetime({body, 0, 5});
  EXPECT_THROW(world.scheduleLifetime({body, 0, 6}), std::invalid_argument) << "one lifetime per body";
  EXPECT_THROW(world.removeBody(7), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, BodyLifetimeTest,
                         ::testing::Values(SolverKind::Seed, SolverKind::SequentialImpulse),
                         [](const auto& info) { return std::string(solverKindName(info.param)); });

// Leaves removed for good rotate their old path by the insertion's rules: a
// row of sorted boxes (the case rotations exist for) loses leaves in a
// shuffled order, the tree stays valid after each removal, rotations happen
// during removals, and the tree ends no taller than one that never rotated.
TEST(TreeRemoval, RotatesLikeInsertionAndStaysValid) {
  const auto build = [](bool rotations) {
    DynamicAabbTreeOptions options;
    options.rotations = rotations;
    auto tree = std::make_unique<DynamicAabbTree>(options);
    std::vector<int> proxies;
    for (int i = 0; i < 256; ++i)
      proxies.push_back(tree->createProxy(Aabb{Vec3(i, 0, 0), Vec3(i + 0.8, 1, 1)}, i));
    return std::make_pair(std::move(tree), proxies);
  };
  auto [rotating, rotatingProxies] = build(true);
  auto [plain, plainProxies] = build(false);
  std::vector<int> order(256);
  for (int i = 0; i < 256; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  rotating->setRotationLogEnabled(true);
  rotating->clearRotationLog();
  for (int k = 0; k < 192; ++k) {
    rotating->destroyProxy(rotatingProxies[order[k]]);
    plain->destroyProxy(plainProxies[order[k]]);
    ASSERT_EQ(rotating->validate(), "") << "after removal " << k;
    ASSERT_EQ(plain->validate(), "") << "after removal " << k;
  }
  EXPECT_FALSE(rotating->rotationLog().empty());
  EXPECT_EQ(rotating->proxyCount(), 64);
  EXPECT_LE(rotating->height(), plain->height());
  EXPECT_LE(rotating->internalArea(), plain->internalArea());
}

}  // namespace
}  // namespace physdbg

namespace physdbg {
namespace {

// A destroyed body's id is refused from then on, never silently taken by a
// later body: the next body gets a new id, and every call that would act on
// or hand out the destroyed one throws, naming it.
TEST(DestroyedBody, ItsIdIsRefusedAndNeverReused) {
  World world;
  world.addBody(testbodies::floorSlab());
  const BodyId gone = world.addBody(testbodies::box(Vec3(0, 0.5, 0)));
  const BodyId top = world.addBody(testbodies::box(Vec3(0, 1.5, 0)));
  for (int step = 0; step < 60; ++step) world.step();
  const Vec3 last = world.bodies()[gone].position();
  world.destroyBody(gone);
  EXPECT_TRUE(world.isDestroyed(gone));
  EXPECT_FALSE(world.isPresent(gone));
  const BodyId next = world.addBody(testbodies::ball(Vec3(3, 2, 0)));
  EXPECT_NE(next, gone);
  EXPECT_EQ(next, top + 1);
  const auto refuses = [&](const char* what, const auto& call) {
    try {
      call();
      ADD_FAILURE() << what << " accepted a destroyed body's id";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("body " + std::to_string(gone) + " was destroyed"), std::string::npos)
          << what << ": " << error.what();
    }
  };
  refuses("body", [&] { world.body(gone); });
  refuses("const body", [&] { static_cast<const World&>(world).body(gone); });
  refuses("sleep", [&] { world.sleep(gone); });
  refuses("wake", [&] { world.wake(gone); });
  refuses("removeBody", [&] { world.removeBody(gone); });
  refuses("restoreBody", [&] { world.restoreBody(gone); });
  refuses("destroyBody", [&] { world.destroyBody(gone); });
  refuses("scheduleForce", [&] { world.scheduleForce({gone, Vec3(1, 0, 0), false, ForceMode::Force, {}, 100, 101}); });
  refuses("scheduleState", [&] {
    ScheduledState state;
    state.body = gone;
    state.step = 100;
    state.linearVelocity = Vec3(1, 0, 0);
    world.scheduleState(state);
  });
  refuses("scheduleLifetime", [&] { world.scheduleLifetime({gone, 0, 200}); });
  // What rested on it falls, and the run goes on without it.
  for (int step = 0; step < 60; ++step) world.step();
  EXPECT_LT(world.body(top).position().y(), 1.0);
  EXPECT_EQ(world.bodies()[gone].position(), last) << "its last state is kept, untouched";
}

// A body destroyed before its scheduled return does not come back.
TEST(DestroyedBody, DropsItsLifetime) {
  World world;
  world.addBody(testbodies::floorSlab());
  const BodyId later = world.addBody(testbodies::box(Vec3(0, 0.5, 0)));
  world.scheduleLifetime({later, 10, {}});
  world.destroyBody(later);
  for (int step = 0; step < 20; ++step) world.step();
  EXPECT_FALSE(world.isPresent(later));
}

}  // namespace
}  // namespace physdbg
