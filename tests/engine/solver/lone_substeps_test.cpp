// A body resting alone on something immovable takes loneSubsteps; stacks,
// piles and bodies in flight keep the full substeps (SolverSettings).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

// Unit boxes stacked on the floor (top at y = 0), never asleep.
World boxStack(int boxes, int loneSubsteps = SolverSettings{}.loneSubsteps) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.solver.loneSubsteps = loneSubsteps;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  for (int i = 0; i < boxes; ++i) world.addBody(testbodies::box(Vec3(0, 0.5 + i, 0)));
  return world;
}

void run(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

TEST(LoneSubsteps, ABoxRestingAloneTakesLoneSubsteps) {
  World world = boxStack(1);
  run(world, 60);
  EXPECT_EQ(world.lastStepStats().substeps, SolverSettings{}.loneSubsteps);
  World fixed = boxStack(1, SolverSettings{}.substeps);
  run(fixed, 60);
  EXPECT_EQ(fixed.lastStepStats().substeps, SolverSettings{}.substeps);
}

TEST(LoneSubsteps, AStackKeepsTheFullSubsteps) {
  World world = boxStack(2);
  run(world, 60);
  EXPECT_EQ(world.lastStepStats().substeps, SolverSettings{}.substeps);
}

// The contact's frequency does not depend on the substeps (a quarter of 4
// substeps' rate at 60 Hz is the default 60 Hz), so a box settles to the same
// overlap, g / omega^2 = 9.81 / (2 pi 60)^2 = 0.07 mm, with 4 or 8 substeps.
TEST(LoneSubsteps, ABoxSettlesAsDeepWithFewerSubsteps) {
  World lone = boxStack(1);
  World fixed = boxStack(1, SolverSettings{}.substeps);
  run(lone, 120);
  run(fixed, 120);
  const double overlap = 0.5 - lone.body(1).position().y(), reference = 0.5 - fixed.body(1).position().y();
  EXPECT_NEAR(overlap, reference, 1e-5);
  EXPECT_LT(std::abs(overlap), 1e-3);
  EXPECT_LT(lone.body(1).linearVelocity().norm(), 1e-6);
}

// A box falling onto the floor is in flight (speculative contacts only)
// until it lands: it keeps the full substeps for the impact.
TEST(LoneSubsteps, ABoxInFlightKeepsTheFullSubsteps) {
  WorldSettings settings;
  settings.allowSleep = false;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  BodyDefinition box = testbodies::box(Vec3(0, 0.53, 0));  // 3 cm up: a speculative contact
  box.linearVelocity = Vec3(0, -3, 0);
  world.addBody(box);
  world.step();
  EXPECT_GT(world.lastStepStats().manifoldPoints, 0);
  EXPECT_EQ(world.lastStepStats().substeps, SolverSettings{}.substeps);
}

}  // namespace
}  // namespace physdbg
