// A calm island takes calmSubsteps: a body resting alone on something
// immovable, or bodies at rest together. Bodies landing, sliding or pushed
// apart from a deep overlap keep the full substeps (SolverSettings).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

const SolverSettings defaults;

// Unit boxes stacked on the floor (top at y = 0), never asleep; `overlap`
// sinks every box that far into the one below.
World boxStack(int boxes, int calmSubsteps = defaults.calmSubsteps, double overlap = 0.0) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.solver.calmSubsteps = calmSubsteps;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  for (int i = 0; i < boxes; ++i) world.addBody(testbodies::box(Vec3(0, 0.5 + i * (1.0 - overlap), 0)));
  return world;
}

void run(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

// One box resting alone, and a stack of four at rest; calmSubsteps =
// substeps turns the rule off.
TEST(CalmSubsteps, ABoxAloneAndAStackAtRestTakeCalmSubsteps) {
  for (int boxes : {1, 4}) {
    World world = boxStack(boxes);
    run(world, 60);
    EXPECT_EQ(world.lastStepStats().substeps, defaults.calmSubsteps) << boxes << " boxes";
    World fixed = boxStack(boxes, defaults.substeps);
    run(fixed, 60);
    EXPECT_EQ(fixed.lastStepStats().substeps, defaults.substeps) << boxes << " boxes";
  }
}

struct Sway {
  double height = 0, wander = 0, speed = 0;  // top box; largest over the run
};

// Steps 60-600 of a ten-box stack: the top box's final height, its largest
// horizontal distance from the axis, and the largest speed of any box.
Sway swayOfTenBoxes(int calmSubsteps) {
  World world = boxStack(10, calmSubsteps);
  run(world, 60);
  Sway sway;
  for (int step = 60; step < 600; ++step) {
    world.step();
    const Vec3 top = world.body(10).position();
    sway.height = top.y();
    sway.wander = std::max(sway.wander, std::hypot(top.x(), top.z()));
    for (std::size_t id = 1; id <= 10; ++id) sway.speed = std::max(sway.speed, world.body(id).linearVelocity().norm());
  }
  return sway;
}

// Each contact of ten boxes holds at most 9 kg on the default 60 Hz spring,
// whatever the substeps, so the stack settles to the same height. Rounding
// leaves a perfect stack swaying by a fraction of a millimetre with the full
// substeps too; with calm ones it may sway a little more, never topple.
TEST(CalmSubsteps, ATallStackStandsAsWellWithCalmSubsteps) {
  const Sway calm = swayOfTenBoxes(defaults.calmSubsteps), full = swayOfTenBoxes(defaults.substeps);
  std::printf("[ measured ] top box wander (m): calm %g, full %g; largest speed (m/s): calm %g, full %g\n", calm.wander,
              full.wander, calm.speed, full.speed);
  EXPECT_NEAR(calm.height, full.height, 1e-4);
  EXPECT_LT(calm.wander, 0.005);              // half a percent of a box's side
  EXPECT_LT(calm.speed, defaults.calmSpeed);  // it stays calm
}

// The contact's frequency does not depend on the substeps (a quarter of 4
// substeps' rate at 60 Hz is the default 60 Hz), so a box settles to the same
// overlap, g / omega^2 = 9.81 / (2 pi 60)^2 = 0.07 mm, with 4 or 8 substeps.
TEST(CalmSubsteps, ABoxSettlesAsDeepWithFewerSubsteps) {
  World calm = boxStack(1);
  World fixed = boxStack(1, defaults.substeps);
  run(calm, 120);
  run(fixed, 120);
  const double overlap = 0.5 - calm.body(1).position().y(), reference = 0.5 - fixed.body(1).position().y();
  EXPECT_NEAR(overlap, reference, 1e-5);
  EXPECT_LT(std::abs(overlap), 1e-3);
  EXPECT_LT(calm.body(1).linearVelocity().norm(), 1e-6);
}

// Below 4 calm substeps the contact softens to a quarter of their rate: with
// 2, a box alone rests on a 30 Hz spring, g / omega^2 = 9.81 / (2 pi 30)^2 =
// 0.276 mm deep. An island takes as many as its load needs: the floor contact
// under ten unit boxes holds 2.5 kg per corner on an effective mass of
// 0.25 kg, which needs 31.5 Hz to settle within restingOverlap (2.5 mm), so
// the stack takes 3 substeps at 45 Hz; under four boxes 2 at 30 Hz do.
TEST(CalmSubsteps, FewerThanFourSoftenTheContactAsFarAsTheLoadAllows) {
  World lone = boxStack(1, 2);
  run(lone, 120);
  EXPECT_EQ(lone.lastStepStats().substeps, 2);
  EXPECT_DOUBLE_EQ(lone.lastStepStats().contactHertz, 30.0);
  EXPECT_NEAR(0.5 - lone.body(1).position().y(), 9.81 / std::pow(2.0 * std::numbers::pi * 30.0, 2), 1e-5);
  for (const auto& [boxes, substeps] : {std::pair{4, 2}, std::pair{10, 3}}) {
    World stack = boxStack(boxes, 2);
    run(stack, 120);
    EXPECT_EQ(stack.lastStepStats().substeps, substeps) << boxes << " boxes";
    EXPECT_DOUBLE_EQ(stack.lastStepStats().contactHertz, 15.0 * substeps) << boxes << " boxes";
    EXPECT_LT(stack.lastStepStats().largestPenetration, defaults.restingOverlap) << boxes << " boxes";
  }
}

// A box falling onto the floor is in flight (speculative contacts only)
// until it lands: it keeps the full substeps for the impact.
TEST(CalmSubsteps, ABoxInFlightKeepsTheFullSubsteps) {
  WorldSettings settings;
  settings.allowSleep = false;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  BodyDefinition box = testbodies::box(Vec3(0, 0.53, 0));  // 3 cm up: a speculative contact
  box.linearVelocity = Vec3(0, -3, 0);
  world.addBody(box);
  world.step();
  EXPECT_GT(world.lastStepStats().manifoldPoints, 0);
  EXPECT_EQ(world.lastStepStats().substeps, defaults.substeps);
}

// A box about to land on a resting stack joins its island and makes it busy.
TEST(CalmSubsteps, ABoxLandingOnAStackTakesTheFullSubsteps) {
  World world = boxStack(2);
  run(world, 60);
  ASSERT_EQ(world.lastStepStats().substeps, defaults.calmSubsteps);
  BodyDefinition box = testbodies::box(Vec3(0, 2.53, 0));
  box.linearVelocity = Vec3(0, -3, 0);
  world.addBody(box);
  world.step();
  EXPECT_EQ(world.lastStepStats().substeps, defaults.substeps);
}

// calmSpeed is the line: the same stack set sliding just under and just over
// it (the top box, rim speed included for a spin).
TEST(CalmSubsteps, MotionAboveCalmSpeedTakesTheFullSubsteps) {
  const double speed = defaults.calmSpeed;
  for (const auto& [velocity, spin, substeps] :
       std::vector<std::tuple<Vec3, Vec3, int>>{{Vec3(0.9 * speed, 0, 0), Vec3::Zero(), defaults.calmSubsteps},
                                                {Vec3(1.1 * speed, 0, 0), Vec3::Zero(), defaults.substeps},
                                                {Vec3::Zero(), Vec3(0, 0.9 * speed, 0), defaults.calmSubsteps},
                                                {Vec3::Zero(), Vec3(0, 1.1 * speed, 0), defaults.substeps}}) {
    World world = boxStack(2);
    run(world, 60);
    world.body(2).setLinearVelocity(velocity);
    world.body(2).setAngularVelocity(spin);
    world.step();
    EXPECT_EQ(world.lastStepStats().substeps, substeps) << velocity.transpose() << " " << spin.transpose();
  }
}

// A box of a resting stack moved 5 cm down into the one below, still at
// rest: far deeper than resting contacts settle at, so the stack is pushed
// apart with the full substeps, then calms down again.
TEST(CalmSubsteps, ADeepOverlapTakesTheFullSubsteps) {
  World world = boxStack(3);
  run(world, 60);
  ASSERT_EQ(world.lastStepStats().substeps, defaults.calmSubsteps);
  world.body(3).setPosition(world.body(3).position() - Vec3(0, 0.05, 0));
  world.step();
  EXPECT_EQ(world.lastStepStats().substeps, defaults.substeps);
  run(world, 120);
  EXPECT_EQ(world.lastStepStats().substeps, defaults.calmSubsteps);
}

// A stack starts calm only after a quarter second at rest.
TEST(CalmSubsteps, AnIslandIsCalmOnlyAfterAQuarterSecondAtRest) {
  World world = boxStack(2);
  world.step();
  EXPECT_EQ(world.lastStepStats().substeps, defaults.substeps);
  run(world, 60);
  EXPECT_EQ(world.lastStepStats().substeps, defaults.calmSubsteps);
}

// Masses spanning more than a factor of 10 keep the full substeps, even at
// rest: Gauss-Seidel carries a load between them slowly.
TEST(CalmSubsteps, AStackOfVeryDifferentMassesKeepsTheFullSubsteps) {
  for (const auto& [lower, substeps] :
       std::vector<std::pair<double, int>>{{9.0, defaults.calmSubsteps}, {11.0, defaults.substeps}}) {
    WorldSettings settings;
    settings.allowSleep = false;
    World world(settings);
    world.addBody(testbodies::floorSlab());
    BodyDefinition heavy = testbodies::box(Vec3(0, 0.5, 0)), light = testbodies::box(Vec3(0, 1.5, 0));
    heavy.mass = lower;
    world.addBody(heavy);
    world.addBody(light);
    run(world, 60);
    EXPECT_EQ(world.lastStepStats().substeps, substeps) << lower << " kg under 1 kg";
  }
}

}  // namespace
}  // namespace physdbg
