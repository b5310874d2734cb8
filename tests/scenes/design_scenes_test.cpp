// The design's scenes (scenes/design_scenes.h): they build, keep their balls
// in the enclosure, and the broad-phase variants change the work, never the
// motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/world.h"
#include "scenes/design_scenes.h"

namespace physdbg {
namespace {

const BuiltinScene& designScene(const std::string& name) {
  static const std::vector<BuiltinScene> scenes = designScenes();
  const auto found = std::find_if(scenes.begin(), scenes.end(), [&](const BuiltinScene& s) { return s.name == name; });
  if (found == scenes.end()) throw std::invalid_argument("no design scene " + name);
  return *found;
}

// The scenes ship with the design's response (seed); the claims below hold
// for our sequential impulses too, so they are checked under both.
constexpr SolverKind bothSolvers[] = {SolverKind::Seed, SolverKind::SequentialImpulse};

SceneDescription withSolver(const std::string& name, SolverKind solver) {
  SceneDescription scene = designScene(name).make();
  scene.world.solver.kind = solver;
  return scene;
}

World runScene(const std::string& name, int steps, SolverKind solver = SolverKind::Seed) {
  World world = buildWorld(withSolver(name, solver));
  for (int i = 0; i < steps; ++i) world.step();
  return world;
}

TEST(DesignScenes, AreTheDesignsSetWithOneLineDescriptions) {
  std::vector<std::string> names;
  for (const BuiltinScene& entry : designScenes()) {
    names.push_back(entry.name);
    EXPECT_FALSE(entry.description.empty());
    EXPECT_EQ(entry.description.find('\n'), std::string::npos);
    const SceneDescription scene = entry.make();
    EXPECT_EQ(scene.name, entry.name);
    EXPECT_EQ(scene.description, entry.description);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"balls24", "balls48", "balls48_bruteforce", "balls48_no_static_skip",
                                              "balls48_bruteforce_no_static_skip", "bounce"}));
  EXPECT_EQ(designScene("balls24").make().bodies.size(), 24u + 6u);  // floor, 4 walls, ramp
  EXPECT_EQ(designScene("balls48").make().bodies.size(), 48u + 6u);
  const SceneDescription brute = designScene("balls48_bruteforce_no_static_skip").make();
  EXPECT_EQ(brute.world.broadPhase, BroadPhaseKind::BruteForce);
  EXPECT_TRUE(brute.world.bruteForceBothOrders);
  EXPECT_FALSE(brute.world.skipStaticPairs);
  for (const BuiltinScene& entry : designScenes()) {
    SCOPED_TRACE(entry.name);
    EXPECT_EQ(entry.make().world.solver.kind, SolverKind::Seed);  // the design's response
    EXPECT_NE(entry.description.find("seed"), std::string::npos);
  }
}

// Responses are applied in (a, b) order over the touching pairs only, and
// every variant finds the same touching pairs, so the motion is bit-identical;
// only the counters differ.
TEST(DesignScenes, BroadPhaseVariantsGiveBitIdenticalMotion) {
  const int steps = 300;
  for (const SolverKind solver : bothSolvers) {
    SCOPED_TRACE(solver == SolverKind::Seed ? "seed" : "sequential impulses");
    const World reference = runScene("balls48", steps, solver);
    for (const char* name : {"balls48_bruteforce", "balls48_no_static_skip", "balls48_bruteforce_no_static_skip"}) {
      SCOPED_TRACE(name);
      const World variant = runScene(name, steps, solver);
      ASSERT_EQ(variant.bodyCount(), reference.bodyCount());
      for (BodyId id = 0; id < reference.bodyCount(); ++id) {
        ASSERT_EQ(variant.body(id).position(), reference.body(id).position()) << "body " << id;
        ASSERT_EQ(variant.body(id).linearVelocity(), reference.body(id).linearVelocity()) << "body " << id;
      }
    }
  }
  EXPECT_EQ(runScene("balls48_no_static_skip", 1).lastStepStats().staticPairsTested, 15);  // 6 statics: 6*5/2
  EXPECT_EQ(runScene("balls48", 1).lastStepStats().staticPairsTested, 0);
}

// Walls stand at |x|, |z| = 4 with balls of radius 0.5. A ball squeezed by
// the pile may sink into a wall or the floor by a fraction of its radius (one
// contact point per pair, one pass), but none may pass through.
TEST(DesignScenes, BallsStayInsideTheEnclosure) {
  for (const SolverKind solver : bothSolvers) {
    for (const char* name : {"balls24", "balls48"}) {
      SCOPED_TRACE(std::string(name) + (solver == SolverKind::Seed ? " seed" : " sequential impulses"));
      World world = buildWorld(withSolver(name, solver));
      for (int i = 0; i < 600; ++i) {
        world.step();
        for (const RigidBody& body : world.bodies()) {
          if (body.isStatic()) continue;
          ASSERT_LT(std::max(std::abs(body.position().x()), std::abs(body.position().z())), 4.0) << "step " << i;
          ASSERT_GT(body.position().y(), 0.0) << "step " << i;
        }
      }
      EXPECT_TRUE(world.numericalFaults().empty());
    }
  }
}

// Apex of each ball (height of its bottom) after its first bounce within 3 s.
std::vector<double> bounceApexes(SolverKind solver) {
  World world = buildWorld(withSolver("bounce", solver));
  std::vector<double> apex(world.bodyCount(), 0.0);
  std::vector<bool> bounced(world.bodyCount(), false);
  for (int i = 0; i < 180; ++i) {
    world.step();
    for (BodyId id = 1; id < world.bodyCount(); ++id) {
      const RigidBody& body = world.body(id);
      if (body.linearVelocity().y() > 0.0) bounced[id] = true;
      if (bounced[id]) apex[id] = std::max(apex[id], body.position().y() - 0.5);
    }
  }
  for (BodyId id = 1; id < world.bodyCount(); ++id)
    if (!bounced[id]) apex[id] = -1.0;  // never left the floor
  return apex;
}

// Four balls dropped from 4 m onto a floor of restitution 0: after the first
// bounce the apex grows with restitution (0 does not bounce at all). Under
// the sequential-impulse solver the pair takes the larger restitution, so
// the apex is about e^2 * 4 m.
TEST(DesignScenes, BounceApexGrowsWithRestitution) {
  const std::vector<double> apex = bounceApexes(SolverKind::SequentialImpulse);
  EXPECT_EQ(apex[1], -1.0);
  EXPECT_GT(apex[2], 0.5 * 0.5 * 4.0 * 0.8);
  EXPECT_GT(apex[3], apex[2]);
  EXPECT_GT(apex[4], apex[3]);
  EXPECT_GT(apex[4], 0.9 * 4.0);
}

// The scene as shipped uses the design's response, which averages the pair's
// restitutions (Unity's default): e/2 against the floor, so the apex is
// about (e/2)^2 * 4 m: 0.25, 0.64 and 1 m.
TEST(DesignScenes, BounceUnderTheSeedResponseAveragesRestitution) {
  EXPECT_EQ(designScene("bounce").make().world.solver.kind, SolverKind::Seed);
  const std::vector<double> apex = bounceApexes(SolverKind::Seed);
  EXPECT_EQ(apex[1], -1.0);
  const double restitutions[] = {0.0, 0.5, 0.8, 1.0};
  for (BodyId id = 2; id <= 4; ++id) {
    const double expected = std::pow(restitutions[id - 1] / 2.0, 2) * 4.0;
    EXPECT_NEAR(apex[id], expected, 0.15 * expected) << "ball " << id;
  }
  EXPECT_GT(apex[3], apex[2]);
  EXPECT_GT(apex[4], apex[3]);
}

}  // namespace
}  // namespace physdbg
