// Issue 6 acceptance: energy and momentum. An elastic sphere never rises above
// its drop height; a free tumbling box gains no energy and keeps its angular
// momentum; equal elastic spheres swap velocities head on; a 200 m/s bullet
// does not tunnel through a 0.1 m wall; the seed solver is still selectable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/colliders/sphere_collider.h"
#include "scenes/stability_scenes.h"
#include "stable_test_helpers.h"

namespace physdbg {
namespace {

using stable::reportFigure;

// The bottom of the sphere, sampled after every step, never exceeds the drop
// height (beyond round-off): bounces may lose energy but never make it.
TEST(StableEnergy, ElasticSphereNeverRisesAboveItsDropHeight) {
  constexpr double dropHeight = 2.0, radius = 0.5;
  World world = buildWorld(elasticDropScene(dropHeight));
  const RigidBody& ball = world.body(1);
  double highest = -std::numeric_limits<double>::infinity(), highestAfterFirstBounce = highest;
  bool bounced = false;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const double bottom = ball.position().y() - radius;
    highest = std::max(highest, bottom);
    bounced = bounced || ball.linearVelocity().y() > 0.0;
    if (bounced) highestAfterFirstBounce = std::max(highestAfterFirstBounce, bottom);
  }
  reportFigure("highest bottom - drop height (m)", highest - dropHeight);
  reportFigure("highest rebound / drop height", highestAfterFirstBounce / dropHeight);
  EXPECT_LE(highest, dropHeight + 1e-12);
  // It really bounces (e = 1): a sphere stuck on the floor would pass the above.
  EXPECT_GT(highestAfterFirstBounce, 0.9 * dropHeight);
}

// MuJoCo's test: explicit Euler ends at 1.09x the initial energy. The
// gyroscopic step must not add energy (1e-6 relative) and may let the angular
// momentum drift by at most 1e-3 relative.
TEST(StableEnergy, TumblingBoxGainsNoEnergyAndKeepsItsAngularMomentum) {
  World world = buildWorld(tumblingBoxScene());
  const RigidBody& box = world.body(0);
  const double initialEnergy = box.kineticEnergy();
  const Vec3 initialMomentum = box.angularMomentum();
  double largestEnergy = initialEnergy, largestDrift = 0.0;
  for (int i = 0; i < 500; ++i) {
    world.step();
    largestEnergy = std::max(largestEnergy, box.kineticEnergy());
    largestDrift = std::max(largestDrift, (box.angularMomentum() - initialMomentum).norm() / initialMomentum.norm());
  }
  reportFigure("tumbling box largest energy / initial - 1", largestEnergy / initialEnergy - 1.0);
  reportFigure("tumbling box largest angular momentum drift (relative)", largestDrift);
  EXPECT_LE(largestEnergy, initialEnergy * (1.0 + 1e-6));
  EXPECT_LT(largestDrift, 1e-3);
  // It did tumble: (1, 2, 3) is not a principal axis, so omega changes.
  EXPECT_GT((box.angularVelocity() - Vec3(1, 2, 3)).norm(), 0.1);
}

TEST(StableEnergy, EqualElasticSpheresSwapVelocitiesHeadOnWithSequentialImpulses) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.allowSleep = false;
  ASSERT_EQ(settings.solver.kind, SolverKind::SequentialImpulse);
  World world(settings);
  BodyDefinition sphere;
  sphere.collider = std::make_shared<SphereCollider>(0.5);
  sphere.mass = 2.0;
  sphere.material.restitution = 1.0;
  sphere.position = Vec3(-1.5, 0, 0);
  sphere.linearVelocity = Vec3(3, 0, 0);
  const BodyId a = world.addBody(sphere);
  sphere.position = Vec3(1.5, 0, 0);
  sphere.linearVelocity = Vec3(-1, 0, 0);
  const BodyId b = world.addBody(sphere);
  const double momentumBefore = 2.0 * 3.0 + 2.0 * -1.0;
  for (int i = 0; i < 60; ++i) world.step();  // they meet after 0.5 s
  const Vec3 velocityA = world.body(a).linearVelocity(), velocityB = world.body(b).linearVelocity();
  reportFigure("head-on velocity error", std::max((velocityA - Vec3(-1, 0, 0)).norm(), (velocityB - Vec3(3, 0, 0)).norm()));
  EXPECT_NEAR(velocityA.x(), -1.0, 1e-9);
  EXPECT_NEAR(velocityB.x(), 3.0, 1e-9);
  EXPECT_NEAR(2.0 * velocityA.x() + 2.0 * velocityB.x(), momentumBefore, 1e-12 * 8.0);
  EXPECT_LT(velocityA.tail<2>().norm() + velocityB.tail<2>().norm(), 1e-12);
  EXPECT_LT(world.body(a).angularVelocity().norm() + world.body(b).angularVelocity().norm(), 1e-12);
}

struct BulletRun {
  double deepest = 0.0;         // furthest the bullet's front got past the near face, m
  double largestReboundSpeed = 0.0;
  double largestSpin = 0.0;     // rad/s
  bool passedThrough = false;   // reached the far face, or ended beyond the near one
};

// Five start offsets, so the bullet arrives at five different phases of a step.
// `tilt` turns the bullet about an oblique axis before it flies.
BulletRun fireBullets(BulletShape shape, double tilt = 0.0) {
  BulletRun run;
  for (int phase = 0; phase < 5; ++phase) {
    SceneDescription scene = bulletScene(200.0, shape);
    scene.bodies[1].position.x() -= 0.37 * phase;
    scene.bodies[1].orientation = Quat(Eigen::AngleAxisd(tilt, Vec3(0.3, 0.5, 0.8).normalized()));
    World world = buildWorld(scene);
    const RigidBody& bullet = world.body(1);
    for (int i = 0; i < scene.steps; ++i) {
      world.step();
      const double front = bullet.collider().worldBounds(bullet.transform()).max.x();
      run.deepest = std::max(run.deepest, front + wallHalfThickness);
      run.passedThrough = run.passedThrough || front >= wallHalfThickness;
      run.largestReboundSpeed = std::max(run.largestReboundSpeed, -bullet.linearVelocity().x());
      run.largestSpin = std::max(run.largestSpin, bullet.angularVelocity().norm());
    }
    run.passedThrough = run.passedThrough || bullet.position().x() > -wallHalfThickness;
  }
  reportFigure("bullet deepest penetration past the near face (m)", run.deepest);
  reportFigure("bullet largest rebound speed (m/s, restitution 0)", run.largestReboundSpeed);
  reportFigure("bullet largest spin (rad/s)", run.largestSpin);
  return run;
}

// The criterion: zero pass-through, whatever the arrival phase.
TEST(StableEnergy, SphereBulletAt200MetresPerSecondDoesNotTunnelThroughAThinWall) {
  EXPECT_FALSE(fireBullets(BulletShape::Sphere).passedThrough);
}

TEST(StableEnergy, BoxBulletAt200MetresPerSecondDoesNotTunnelThroughAThinWall) {
  EXPECT_FALSE(fireBullets(BulletShape::Box).passedThrough);
}

// Stricter, as Box2D reports: the bullet stops at the near face (within 1 cm),
// without bouncing back (restitution 0) or spinning up (it hits face on).
void expectBulletStopsAtTheNearFace(BulletShape shape, double tilt = 0.0) {
  const BulletRun run = fireBullets(shape, tilt);
  EXPECT_LT(run.deepest, 0.01);
  EXPECT_LT(run.largestReboundSpeed, 0.05);
  EXPECT_LT(run.largestSpin, 0.1);
}

TEST(StableEnergy, SphereBulletStopsAtTheNearFace) { expectBulletStopsAtTheNearFace(BulletShape::Sphere); }

// Face on up to rounding, or a micro-radian off: the four corners' gaps
// differ in the last bits or a little more, and the approach solve must find
// the case that holds (every corner pushing, none, or some) instead of
// falling back to the point-by-point solve on the signs of zeros (it did:
// 10.9 rad/s and a 0.28 m/s rebound at 1e-12 rad). A milliradian gives
// 0.2 rad/s and 1.5 mm/s, a centiradian 2.1 rad/s and 1.5 cm/s.
TEST(StableEnergy, BoxBulletTiltedByRoundingStopsAtTheNearFace) {
  for (const double tilt : {1e-12, 1e-9, 1e-6}) {
    SCOPED_TRACE(tilt);
    expectBulletStopsAtTheNearFace(BulletShape::Box, tilt);
  }
}

TEST(StableEnergy, BoxBulletStopsAtTheNearFace) {
  expectBulletStopsAtTheNearFace(BulletShape::Box);
}

// The design's one-point response is still there: it resolves contacts
// without manifolds, and a dropped sphere still comes to rest on the floor.
TEST(StableEnergy, SeedSolverIsStillSelectable) {
  SceneDescription scene = elasticDropScene(1.0);
  scene.bodies[1].material.restitution = 0.0;
  scene.world.solver.kind = SolverKind::Seed;
  World world = buildWorld(scene);
  int responses = 0;
  for (int i = 0; i < 120; ++i) {
    world.step();
    responses += world.lastStepStats().responses;
    EXPECT_TRUE(world.manifolds().empty());
  }
  EXPECT_GT(responses, 0);
  EXPECT_NEAR(world.body(1).position().y(), 0.5, 0.05);
  EXPECT_LT(world.body(1).linearVelocity().norm(), 0.2);
}

}  // namespace
}  // namespace physdbg
