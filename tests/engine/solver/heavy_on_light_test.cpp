// Heavy bodies on light ones (SolverSettings::massRatioLimit): a 1 kg box
// under 10,000 kg holds, a 1 kg / 1e6 kg / 1 kg stack never sinks into the
// floor, and ordinary mass ratios are solved exactly as without the scaling.
// Sideways too: a light box a heavy one pushes against a wall stays out of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/world.h"
#include "tests/engine/stable_test_helpers.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

// Unit boxes stacked on the floor (top at y = 0), bottom first. Never
// asleep, so every step of the run is solved.
World massStack(const std::vector<double>& masses, double massRatioLimit = SolverSettings{}.massRatioLimit) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.solver.massRatioLimit = massRatioLimit;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  for (std::size_t i = 0; i < masses.size(); ++i) {
    BodyDefinition box = testbodies::box(Vec3(0, 0.5 + static_cast<double>(i), 0));
    box.mass = masses[i];
    world.addBody(box);
  }
  return world;
}

// Overlap of box i with what is under it (the floor for box 1), m.
double overlapBelow(const World& world, BodyId box) {
  const double under = box == 1 ? 0.0 : world.body(box - 1).position().y() + 0.5;
  return under - (world.body(box).position().y() - 0.5);
}

TEST(HeavyOnLight, TenTonnesOnOneKilogramHolds) {
  World world = massStack({1.0, 10'000.0});
  double deepest = 0.0, drift = 0.0;
  for (int step = 0; step < 600; ++step) {
    world.step();
    for (BodyId box : {1u, 2u}) {
      deepest = std::max(deepest, overlapBelow(world, box));
      drift = std::max(drift, std::hypot(world.body(box).position().x(), world.body(box).position().z()));
    }
  }
  EXPECT_LT(deepest, 0.01) << "overlap under 1 cm";
  EXPECT_LT(drift, 0.01);
  EXPECT_TRUE(world.numericalFaults().empty());
}

// Without the scaling the light box is crushed into the floor: the test
// above fails with massRatioLimit 0 (measured: 5.6 cm deep), so it measures
// the mechanism.
TEST(HeavyOnLight, WithoutScalingTheLightBoxIsCrushed) {
  World world = massStack({1.0, 10'000.0}, 0.0);
  double deepest = 0.0;
  for (int step = 0; step < 600; ++step) {
    world.step();
    for (BodyId box : {1u, 2u}) deepest = std::max(deepest, overlapBelow(world, box));
  }
  EXPECT_GT(deepest, 0.01);  // the limit the test above holds
}

TEST(HeavyOnLight, OneKilogramUnderAMillionNeverSinksIntoTheFloor) {
  World world = massStack({1.0, 1e6, 1.0});
  for (int step = 0; step < 600; ++step) {
    world.step();
    for (BodyId box = 1; box <= 3; ++box) {
      ASSERT_TRUE(world.body(box).position().allFinite());
      ASSERT_GT(world.body(box).position().y() - 0.5, -0.01) << "box " << box << " below the floor, step " << step;
    }
    ASSERT_LT(overlapBelow(world, 2), 0.01) << "step " << step;
  }
}

// A ratio at the limit (10 kg on 0.1 kg) is not scaled: the run is bit for
// bit the run with the scaling off.
TEST(HeavyOnLight, RatiosUpToTheLimitAreUntouched) {
  World scaled = massStack({0.1, 10.0, 0.1, 10.0});
  World plain = massStack({0.1, 10.0, 0.1, 10.0}, 0.0);
  for (int step = 0; step < 240; ++step) {
    scaled.step();
    plain.step();
  }
  for (BodyId box = 1; box <= 4; ++box) EXPECT_EQ(scaled.body(box).position(), plain.body(box).position());
}

// A 0.1 kg box on the floor between a static wall and a 100 kg box that a
// steady 2000 N pushes towards the wall (a heavy pile leaning on it). Both
// boxes stand on the floor, one contact from the ground, and nothing here is
// along gravity, so neither the ground-up order of the mass scaling nor the
// weights tell the solver about this load. The lighter body of the two
// counts as the lower one (supportMassScales), and what the contacts carried
// last step sets their stiffness (loadedHertz). Without both, the light box
// ends 24 cm inside the wall; at 60 Hz a soft contact alone would settle
// 2000 N / (0.1 kg (2 pi 60 Hz)^2) = 14 cm deep.
struct Squeeze {
  World world;
  BodyId light = 0, heavy = 0;
};

Squeeze sidewaysSqueeze() {
  WorldSettings settings;
  settings.allowSleep = false;
  Squeeze squeeze{World(settings)};
  World& world = squeeze.world;
  world.addBody(testbodies::floorSlab());
  BodyDefinition wall = testbodies::box(Vec3(-0.75, 1.0, 0));
  wall.collider = std::make_shared<BoxCollider>(Vec3(0.5, 1.0, 1.0));
  wall.isStatic = true;
  world.addBody(wall);
  BodyDefinition light = testbodies::box(Vec3(0.0, 0.25, 0), 0.25);
  light.mass = 0.1;
  squeeze.light = world.addBody(light);
  BodyDefinition heavy = testbodies::box(Vec3(0.75, 0.5, 0));
  heavy.mass = 100.0;
  squeeze.heavy = world.addBody(heavy);
  return squeeze;
}

TEST(HeavyOnLight, ALightBoxPushedSidewaysStaysOutOfTheWall) {
  Squeeze squeeze = sidewaysSqueeze();
  World& world = squeeze.world;
  double intoWall = 0.0, intoLight = 0.0;
  for (int step = 0; step < 600; ++step) {
    world.body(squeeze.heavy).addForce(Vec3(-2000.0, 0, 0));
    world.step();
    const double lightLeft = world.body(squeeze.light).position().x() - 0.25;
    intoWall = std::max(intoWall, -0.25 - lightLeft);
    const double heavyLeft = world.body(squeeze.heavy).position().x() - 0.5;
    intoLight = std::max(intoLight, lightLeft + 0.5 - heavyLeft);
  }
  stable::reportFigure("light box into the wall (m)", intoWall);
  stable::reportFigure("heavy box into the light one (m)", intoLight);
  EXPECT_LT(intoWall, 0.01) << "light box into the wall";
  EXPECT_LT(intoLight, 0.01) << "heavy box into the light one";
  EXPECT_GT(world.body(squeeze.light).position().y(), 0.24);
  EXPECT_TRUE(world.numericalFaults().empty());
}

}  // namespace
}  // namespace physdbg
