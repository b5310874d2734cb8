// The accuracy report's Bullet series: Bullet integrates semi-implicit Euler
// (v += g h, then x += v h), so after n steps of h a free fall is at
// y_n = -g h^2 n (n + 1) / 2, below the analytic -g (n h)^2 / 2 by g h T / 2.
// The report's free-fall error for Bullet must be that, to float rounding.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/bullet_world.h"
#include "cli/bullet_peer_runs.h"
#include "engine/colliders/sphere_collider.h"
#include "reports/accuracy_references.h"

namespace {

constexpr double g = 9.81;

const physdbg::reports::TimeStepReference& freeFall() {
  static const auto references = physdbg::reports::timeStepReferences();
  return references.front();
}

// Bullet is single precision. Each step rounds the velocity and the position
// (both below 16 in magnitude here) by at most half an ulp, 2^-21, and the
// n - k later steps carry a velocity error on into the position: at most
// n (n h + 1) 2^-21 in all. Rounding dt and g to float adds 3 x 2^-24 of |y|.
double floatTolerance(int steps, double h) {
  return steps * (steps * h + 1.0) * std::ldexp(1.0, -21) + 3.0 * std::ldexp(1.0, -24) * 0.5 * g * std::pow(steps * h, 2);
}

TEST(BulletPeerRuns, FreeFallErrorIsSemiImplicitEulers) {
  if (!physdbg::bench::BulletWorld::available()) GTEST_SKIP() << "built without Bullet";
  ASSERT_EQ(freeFall().name, "free_fall");
  const auto bullet = physdbg::cli::bulletSimulation();
  for (const int rate : {30, 60, 120, 240}) {
    physdbg::WorldSettings settings;
    settings.dt = 1.0 / rate;
    const double expected = g * settings.dt * 1.0 / 2.0;  // T = 1 s
    const double error = freeFall().runIn(settings, bullet).error;
    EXPECT_NEAR(error, expected, floatTolerance(rate, settings.dt)) << "dt 1/" << rate;
  }
}

// The sign, which the error's magnitude hides (explicit Euler would lag by
// as much as semi-implicit Euler leads): Bullet falls further than the
// analytic curve, exactly to the recurrence.
TEST(BulletPeerRuns, FreeFallFollowsTheSemiImplicitRecurrence) {
  if (!physdbg::bench::BulletWorld::available()) GTEST_SKIP() << "built without Bullet";
  physdbg::SceneDescription scene;
  scene.world.dt = 1.0 / 60.0;
  scene.world.allowSleep = false;
  physdbg::BodyDefinition ball;
  ball.collider = std::make_shared<physdbg::SphereCollider>(0.5);
  scene.bodies.push_back(ball);
  const auto simulation = physdbg::cli::bulletSimulation()(scene);
  const int steps = 60;
  for (int i = 0; i < steps; ++i) simulation->step();
  const double h = scene.world.dt;
  EXPECT_NEAR(simulation->position(0).y(), -g * h * h * steps * (steps + 1) / 2.0, floatTolerance(steps, h));
}

}  // namespace
