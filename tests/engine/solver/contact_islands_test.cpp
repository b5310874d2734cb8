// Islands: which bodies a contact links, and that islands are solved
// independently (a pile's motion does not depend on what else is in the
// world, even when another island needs more substeps).
#include "engine/solver/contact_islands.h"

#include <gtest/gtest.h>

#include <memory>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"
#include "scenes/body_builders.h"
#include "scenes/stability_scenes.h"

namespace physdbg {
namespace {

ContactManifold between(std::uint32_t a, std::uint32_t b) {
  ContactManifold manifold;
  manifold.a = a;
  manifold.b = b;
  manifold.pointCount = 1;
  return manifold;
}

std::vector<std::uint32_t> lists(std::span<const std::uint32_t> run) { return {run.begin(), run.end()}; }

TEST(ContactIslands, ImmovableBodiesDoNotLinkIslands) {
  // 0 floor (static), 1-2 a stack, 3-4 another stack, 5 asleep under 6.
  const std::vector<bool> movable = {false, true, true, true, true, false, true};
  const std::vector<ContactManifold> manifolds = {between(0, 1), between(1, 2), between(0, 3),
                                                  between(3, 4), between(5, 6), between(0, 5)};
  ContactIslands islands;
  buildContactIslands(manifolds, movable, islands);
  ASSERT_EQ(islands.size(), 3u);
  EXPECT_EQ(lists(islands[0].manifolds), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(lists(islands[0].bodies), (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(lists(islands[1].manifolds), (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(lists(islands[1].bodies), (std::vector<std::uint32_t>{3, 4}));
  EXPECT_EQ(lists(islands[2].manifolds), (std::vector<std::uint32_t>{4}));
  EXPECT_EQ(lists(islands[2].bodies), (std::vector<std::uint32_t>{6}));
}

TEST(ContactIslands, AChainJoinsOneIslandWhateverTheManifoldOrder) {
  const std::vector<bool> movable(5, true);
  const std::vector<ContactManifold> manifolds = {between(3, 4), between(0, 1), between(2, 3), between(1, 2)};
  ContactIslands islands;
  buildContactIslands(manifolds, movable, islands);
  ASSERT_EQ(islands.size(), 1u);
  EXPECT_EQ(lists(islands[0].manifolds), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(lists(islands[0].bodies), (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
}

// The same 3-box stack, alone and beside a 0.1 / 10 / 0.1 / 10 kg stack
// (whose bottom box carries 20 kg, so its island takes 12 substeps): its
// boxes follow bit-identical paths, at 8 substeps and then, at rest, the
// calm ones.
TEST(ContactIslands, AStackMovesTheSameWhateverElseIsInTheWorld) {
  SceneDescription alone = massStackScene({1.0, 1.0, 1.0});
  SceneDescription shared = alone;
  const double masses[] = {0.1, 10.0, 0.1, 10.0};
  for (int level = 0; level < 4; ++level) {
    BodyDefinition box = alone.bodies[1];
    box.mass = masses[level];
    box.position = Vec3(3.0, 0.5 + level, 0.0);
    shared.bodies.push_back(box);
  }
  World first = buildWorld(alone), second = buildWorld(shared);
  int most = 0;
  for (int i = 0; i < 120; ++i) {
    first.step();
    second.step();
    most = std::max(most, second.lastStepStats().substeps);
    EXPECT_LE(first.lastStepStats().substeps, 8);
  }
  EXPECT_EQ(first.lastStepStats().substeps, SolverSettings{}.calmSubsteps);
  EXPECT_GT(most, 8);
  for (BodyId id = 1; id <= 3; ++id) {
    EXPECT_EQ(first.body(id).position(), second.body(id).position()) << "body " << id;
    EXPECT_EQ(first.body(id).orientation().coeffs(), second.body(id).orientation().coeffs()) << "body " << id;
  }
}

// A touch that wakes a sleeping body makes the world run the narrow phase
// a second time in that step. That must not cost any other island its warm
// start: a stack settling at x = 0 moves bit for bit as it does alone while,
// 5 m away, a ball lands on a box that fell asleep long before.
TEST(ContactIslands, ATouchWakeElsewhereKeepsEveryIslandsWarmStart) {
  const auto unitBox = [](const Vec3& position) {
    BodyDefinition body;
    body.collider = std::make_shared<BoxCollider>(Vec3::Constant(0.5));
    body.position = position;
    return body;
  };
  const auto worldWith = [&](bool sleeperAndBall) {
    World world;
    BodyDefinition floor;
    floor.collider = std::make_shared<BoxCollider>(Vec3(10, 0.5, 10));
    floor.position = Vec3(0, -0.5, 0);
    floor.isStatic = true;
    world.addBody(floor);
    for (int level = 0; level < 3; ++level) world.addBody(unitBox(Vec3(0, 2.5 + 1.0 * level, 0)));
    if (sleeperAndBall) {
      world.addBody(unitBox(Vec3(5, 0.5, 0)));
      BodyDefinition ball = unitBox(Vec3(5, 6.5, 0));
      ball.collider = std::make_shared<SphereCollider>(0.5);
      world.addBody(ball);
    }
    return world;
  };
  World alone = worldWith(false), shared = worldWith(true);
  bool wokeWhileStackMoved = false;
  for (int step = 0; step < 150; ++step) {
    const bool sleeperWasAsleep = shared.isAsleep(4);
    alone.step();
    shared.step();
    if (sleeperWasAsleep && !shared.isAsleep(4) && !shared.isAsleep(1)) wokeWhileStackMoved = true;
    for (BodyId id = 1; id <= 3; ++id) {
      ASSERT_EQ(alone.body(id).position(), shared.body(id).position()) << "body " << id << ", step " << step + 1;
      ASSERT_EQ(alone.body(id).linearVelocity(), shared.body(id).linearVelocity()) << "body " << id;
    }
  }
  EXPECT_TRUE(wokeWhileStackMoved) << "the scene should wake the sleeper while the stack is awake";
}

}  // namespace
}  // namespace physdbg
