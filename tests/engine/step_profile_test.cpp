// The step's stage times (step_profile.h): they cover the step, the solver's
// islands are part of the solver, and they never change what the world does.
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
  EXPECT_GT(sum.solver, 0.0);
  EXPECT_GT(sum.solverIslands, 0.0);  // the column rests on the floor: islands to solve
  EXPECT_GT(sum.narrowPhase, 0.0);
  EXPECT_LE(sum.total, outside);
  // The stages hold the step: only a few statements between them go untimed.
  const double staged = sum.total - profileStages(sum)[8].seconds;
  EXPECT_STREQ(profileStages(sum)[8].name, "other");
  EXPECT_GT(staged, 0.5 * sum.total);
  EXPECT_LE(staged, sum.total);
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
