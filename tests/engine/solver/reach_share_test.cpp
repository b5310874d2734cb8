// Each body's reach share bounds its part of every pair's contact reach, and
// the world's quick rejection on shares never drops a pair the exact test
// (the tight box grown by the pair's reach) would keep: a sphere just inside
// reach still gets its speculative manifold, one just outside does not.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "engine/baselines/seed_solver.h"
#include "engine/solver/sequential_impulse_solver.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

Vec3 randomVector(std::mt19937_64& random, double scale) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  return Vec3(unit(random), unit(random), unit(random)) * scale;
}

BodyReach randomReach(std::mt19937_64& random) {
  std::uniform_real_distribution<double> exponent(-6.0, 3.0), unit(0.0, 1.0);
  BodyReach reach;
  if (unit(random) > 0.2) reach.linearVelocity = randomVector(random, std::pow(10.0, exponent(random)));
  if (unit(random) > 0.5) reach.acceleration = std::pow(10.0, exponent(random));
  if (unit(random) > 0.5) reach.spin = std::pow(10.0, exponent(random));
  return reach;
}

// contactReach(a, b) <= reachShare(a) + reachShare(b), to rounding, for
// opposed, parallel and random velocities over nine decades.
TEST(ReachShare, BoundsEveryPairsReach) {
  const SolverSettings settings;
  const SequentialImpulseSolver sequential(settings);
  const SeedSolver seed(settings, 0.01);
  const StepContext step;
  std::mt19937_64 random(18);
  for (int trial = 0; trial < 20000; ++trial) {
    BodyReach a = randomReach(random), b = randomReach(random);
    if (trial % 4 == 1) b.linearVelocity = -a.linearVelocity;       // head on
    if (trial % 4 == 2) b.linearVelocity = 0.5 * a.linearVelocity;  // same way
    for (const ContactSolver* solver :
         {static_cast<const ContactSolver*>(&sequential), static_cast<const ContactSolver*>(&seed)}) {
      const double reach = solver->contactReach(a, b, step);
      const double shares = solver->reachShare(a, step) + solver->reachShare(b, step);
      ASSERT_LE(reach, shares * (1.0 + 1e-12)) << "trial " << trial;
    }
  }
}

// Two balls of radius 0.5 whose surfaces are `gap` apart along x, with the
// given velocities and spin, in a world without gravity.
World twoBalls(double gap, const Vec3& velocityA, const Vec3& velocityB, const Vec3& spinB) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.allowSleep = false;
  World world(settings);
  BodyDefinition a = testbodies::ball(Vec3(0, 0, 0)), b = testbodies::ball(Vec3(1.0 + gap, 0, 0));
  a.linearVelocity = velocityA;
  b.linearVelocity = velocityB;
  b.angularVelocity = spinB;
  world.addBody(a);
  world.addBody(b);
  return world;
}

TEST(ReachShare, APairJustInsideReachKeepsItsManifold) {
  struct Motion {
    Vec3 a, b, spinB;
  };
  const std::vector<Motion> motions = {
      {Vec3(3, 0, 0), Vec3(-3, 0, 0), Vec3::Zero()},   // closing head on
      {Vec3(5, 0, 0), Vec3::Zero(), Vec3::Zero()},     // one still
      {Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3::Zero()},    // moving together
      {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 3)},  // sideways, spinning (within the fat margin)
      {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()},      // at rest: the slops alone
  };
  for (const Motion& motion : motions) {
    // The reach the world will use: the solver's, at the step's start.
    const World probe = twoBalls(1.0, motion.a, motion.b, motion.spinB);
    const SequentialImpulseSolver solver(probe.settings().solver);
    const StepContext step{probe.settings().dt, Vec3::Zero(), nullptr};
    const double reach = solver.contactReach(probe.body(0), probe.body(1), step);
    for (const double factor : {0.999999, 1.000001}) {
      World world = twoBalls(factor * reach, motion.a, motion.b, motion.spinB);
      world.step();
      const int expected = factor < 1.0 ? 1 : 0;
      EXPECT_EQ(world.lastStepStats().manifolds, expected)
          << "velocities " << motion.a.transpose() << " / " << motion.b.transpose() << ", gap " << factor
          << " of the reach " << reach;
    }
  }
}

}  // namespace
}  // namespace physdbg
