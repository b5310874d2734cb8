// The step's stage times (step_profile.h): every stage is timed, the stages
// nest in the step, the solver's islands in the solver, and timing never
// changes what the world does. No assertion depends on how fast anything ran.
#include "engine/step_profile.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string_view>

#include "engine/world.h"
#include "test_bodies.h"

namespace physdbg {
namespace {

World pile(int threads) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.threads = threads;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) world.addBody(testbodies::box(Vec3(1.2 * i, 0.5 + 1.0 * j, 0.0)));
  return world;
}

TEST(StepProfile, StagesCoverTheStepAndTheSolverHoldsItsIslands) {
  World world = pile(1);
  StepProfile sum;
  double outside = 0.0;
  for (int step = 0; step < 30; ++step) {
    const auto start = std::chrono::steady_clock::now();
    world.step();
    outside += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const StepProfile& profile = world.lastStepStats().profile;
    for (const ProfileStage& stage : profileStages(profile)) {
      if (std::string_view(stage.name) == "other") continue;  // a difference: may round below zero
      EXPECT_GE(stage.seconds, 0.0) << stage.name;
    }
    EXPECT_LE(profile.solverIslands, profile.solver);
    sum += profile;
  }
  // Every stage does work in this pile, so each was timed: a stage left
  // untimed stays exactly 0. (Only that time passed is asserted: the
  // intervals below nest, whatever the machine's speed.)
  for (const ProfileStage& stage : profileStages(sum)) {
    if (std::string_view(stage.name) == "other") continue;
    EXPECT_GT(stage.seconds, 0.0) << stage.name;
  }
  // The stages are disjoint intervals inside the step's, and the step's lies
  // inside the caller's.
  const double staged = sum.forces + sum.broadPhase + sum.pairs + sum.narrowPhase + sum.manifolds + sum.solver +
                        sum.afterSolve;
  EXPECT_LE(staged, sum.total);
  EXPECT_LE(sum.total, outside);
}

TEST(StepProfile, TimingChangesNoResult) {
  World first = pile(1), second = pile(2);
  for (int step = 0; step < 60; ++step) {
    first.step();
    second.step();
  }
  for (BodyId id = 0; id < first.bodyCount(); ++id)
    EXPECT_EQ(first.body(id).position(), second.body(id).position()) << "body " << id;
}

}  // namespace
}  // namespace physdbg
