// The coloured, wide and threaded contact solve (constraint_colouring.h,
// wide_contact_rows.h): the SIMD lanes give the scalar solve's answer up to
// rounding, 1, 2 or 4 threads give the same body states bit for bit, and an
// island moves as it does alone, whatever batch it is solved in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "engine/solver/simd_lanes.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

// A two-layer 10 x 10 carpet of unit boxes, slightly turned and spread (one
// island of several hundred manifolds, so colours hold enough to be split
// over threads), and beside it five separate three-box stacks (five more
// islands). Never asleep.
World pile(int threads, bool wideContacts) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.threads = threads;
  settings.solver.wideContacts = wideContacts;
  World world(settings);
  world.addBody(testbodies::floorSlab());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (int layer = 0; layer < 2; ++layer)
    for (int row = 0; row < 10; ++row)
      for (int column = 0; column < 10; ++column) {
        BodyDefinition box = testbodies::box(
            Vec3(-6.0 + 1.01 * column + jitter(random), 0.55 + 1.05 * layer, -5.0 + 1.01 * row + jitter(random)));
        box.orientation = Quat(Eigen::AngleAxisd(jitter(random) * 5.0, Vec3::UnitY()));
        world.addBody(box);
      }
  for (int stack = 0; stack < 5; ++stack)
    for (int level = 0; level < 3; ++level)
      world.addBody(testbodies::box(Vec3(7.5, 0.5 + 1.02 * level, -8.0 + 4.0 * stack)));
  return world;
}

void run(World& world, int steps) {
  for (int step = 0; step < steps; ++step) world.step();
}

TEST(WideContactSolve, LanesMatchTheScalarSolve) {
  World scalar = pile(1, false), wide = pile(1, true);
  run(scalar, 30);
  run(wide, 30);
  double position = 0.0, velocity = 0.0;
  for (BodyId id = 0; id < scalar.bodyCount(); ++id) {
    position = std::max(position, (scalar.body(id).position() - wide.body(id).position()).norm());
    velocity = std::max(velocity, (scalar.body(id).linearVelocity() - wide.body(id).linearVelocity()).norm());
  }
  RecordProperty("lanes", simd::width);
  EXPECT_LT(position, 1e-6) << simd::width << " lanes";
  EXPECT_LT(velocity, 1e-4) << simd::width << " lanes";
}

TEST(WideContactSolve, AnyThreadCountGivesTheSameStates) {
  World one = pile(1, true);
  run(one, 40);
  for (int threads : {2, 4}) {
    World many = pile(threads, true);
    run(many, 40);
    for (BodyId id = 0; id < one.bodyCount(); ++id) {
      const BodyMotion &expected = one.body(id).motion(), &actual = many.body(id).motion();
      ASSERT_EQ(expected.position, actual.position) << threads << " threads, body " << id;
      ASSERT_EQ(expected.orientation.coeffs(), actual.orientation.coeffs()) << threads << " threads, body " << id;
      ASSERT_EQ(expected.linearVelocity, actual.linearVelocity) << threads << " threads, body " << id;
      ASSERT_EQ(expected.angularVelocity, actual.angularVelocity) << threads << " threads, body " << id;
    }
  }
}

TEST(WideContactSolve, ScalarSolveIsThreadIndependentToo) {
  World one = pile(1, false), two = pile(2, false);
  run(one, 20);
  run(two, 20);
  for (BodyId id = 0; id < one.bodyCount(); ++id) {
    ASSERT_EQ(one.body(id).position(), two.body(id).position()) << "body " << id;
    ASSERT_EQ(one.body(id).linearVelocity(), two.body(id).linearVelocity()) << "body " << id;
  }
}

// Stacks of three boxes on a 12 x 12 grid, 3 m apart (beyond any contact
// reach), each jittered differently; `only` keeps one stack alone on the floor.
World stacks(int threads, int only = -1) {
  WorldSettings settings;
  settings.allowSleep = false;
  settings.threads = threads;
  World world(settings);
  BodyDefinition floor = testbodies::floorSlab();
  floor.collider = std::make_shared<BoxCollider>(Vec3(20, 0.5, 20));
  world.addBody(floor);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (int stack = 0; stack < 144; ++stack) {
    const Vec3 base(-16.5 + 3.0 * (stack % 12), 0.0, -16.5 + 3.0 * (stack / 12));
    for (int level = 0; level < 3; ++level) {
      BodyDefinition box = testbodies::box(base + Vec3(jitter(random), 0.5 + 1.02 * level, jitter(random)));
      box.orientation = Quat(Eigen::AngleAxisd(4.0 * jitter(random), Vec3::UnitY()));
      if (only < 0 || only == stack) world.addBody(box);
    }
  }
  return world;
}

// 144 islands of 3 manifolds are solved in batches (over threads); one stack
// alone is one batch of one island. Colours, lanes and substeps of an island
// do not depend on its neighbours, so each stack moves bit for bit as alone.
TEST(WideContactSolve, AnIslandMovesAsItDoesAlone) {
  World all = stacks(2);
  run(all, 90);
  EXPECT_EQ(all.lastStepStats().manifolds, 144 * 3);
  for (int stack : {0, 61, 143}) {
    World alone = stacks(1, stack);
    run(alone, 90);
    for (int level = 0; level < 3; ++level) {
      const BodyMotion &expected = alone.body(1 + level).motion(), &actual = all.body(1 + 3 * stack + level).motion();
      ASSERT_EQ(expected.position, actual.position) << "stack " << stack << ", level " << level;
      ASSERT_EQ(expected.orientation.coeffs(), actual.orientation.coeffs()) << "stack " << stack << ", level " << level;
      ASSERT_EQ(expected.linearVelocity, actual.linearVelocity) << "stack " << stack << ", level " << level;
      ASSERT_EQ(expected.angularVelocity, actual.angularVelocity) << "stack " << stack << ", level " << level;
    }
  }
}

}  // namespace
}  // namespace physdbg
