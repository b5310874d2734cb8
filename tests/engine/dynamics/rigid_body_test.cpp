#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"

namespace physdbg {
namespace {

BodyDefinition sphereBody(double radius = 0.5) {
  BodyDefinition body;
  body.collider = std::make_shared<SphereCollider>(radius);
  return body;
}

TEST(RigidBody, FreeFallFollowsTheSemiImplicitEulerRecurrence) {
  WorldSettings settings;
  settings.dt = 1.0 / 60.0;
  World world(settings);
  BodyDefinition definition = sphereBody();
  definition.position = Vec3(1, 100, -2);
  definition.linearVelocity = Vec3(0.5, 3, 0);
  const BodyId id = world.addBody(definition);

  // The sequential-impulse solver integrates in substeps of h = dt / substeps.
  const int substeps = settings.solver.substeps;
  const double h = settings.dt / substeps;
  Vec3 position = definition.position, velocity = definition.linearVelocity;
  for (int step = 1; step <= 600; ++step) {
    world.step();
    for (int substep = 0; substep < substeps; ++substep) {
      velocity += settings.gravity * h;
      position += velocity * h;
    }
    ASSERT_EQ(world.body(id).linearVelocity(), velocity) << "step " << step;
    ASSERT_EQ(world.body(id).position(), position) << "step " << step;
  }
  // Closed form of the recurrence: x_n = x0 + n h v0 + g h^2 n (n + 1) / 2.
  const double n = 600.0 * substeps, dt = h;
  const Vec3 expected = definition.position + n * dt * definition.linearVelocity + settings.gravity * dt * dt * n * (n + 1) / 2;
  EXPECT_NEAR((world.body(id).position() - expected).norm(), 0.0, 1e-12 * expected.norm());
}

TEST(RigidBody, SpinAboutAPrincipalAxisIsKeptExactly) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  BodyDefinition definition;
  definition.collider = std::make_shared<BoxCollider>(Vec3(0.1, 0.2, 0.3));
  definition.angularVelocity = Vec3(0, 2.5, 0);
  const BodyId id = world.addBody(definition);
  for (int step = 0; step < 1000; ++step) world.step();
  EXPECT_EQ(world.body(id).angularVelocity(), Vec3(0, 2.5, 0));
  // The orientation is a rotation about y by w t.
  const double angle = 2.5 * 1000 * settings.dt;
  const Quat expected(Eigen::AngleAxisd(angle, Vec3::UnitY()));
  EXPECT_NEAR(world.body(id).orientation().angularDistance(expected), 0.0, 1e-9);
  EXPECT_NEAR(world.body(id).orientation().norm(), 1.0, 1e-15);
}

TEST(RigidBody, DragDecaysVelocityAsTheRecurrenceSays) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.dt = 0.01;
  World world(settings);
  BodyDefinition definition = sphereBody();
  definition.linearVelocity = Vec3(10, 0, 0);
  definition.angularVelocity = Vec3(0, 0, 4);
  definition.linearDrag = 0.5;
  definition.angularDrag = 2.0;
  const BodyId id = world.addBody(definition);
  for (int step = 0; step < 100; ++step) world.step();
  // v_n = v_0 / (1 + c h)^n over n substeps of h, which tends to
  // v_0 exp(-c t) as h -> 0.
  const int substeps = settings.solver.substeps;
  const double h = 0.01 / substeps;
  EXPECT_NEAR(world.body(id).linearVelocity().x(), 10 / std::pow(1 + 0.5 * h, 100 * substeps), 1e-12);
  EXPECT_NEAR(world.body(id).angularVelocity().z(), 4 / std::pow(1 + 2.0 * h, 100 * substeps), 1e-12);
  EXPECT_NEAR(world.body(id).linearVelocity().x(), 10 * std::exp(-0.5), 10 * 0.5 * 0.5 * 0.01);
}

// The velocity half of one step without gravity, as a solver runs it.
BodyMotion velocityHalf(RigidBody& body, double dt) {
  body.beginStep(Vec3::Zero());
  BodyMotion motion = body.motion();
  integrateVelocity(motion, body.motionProperties(), dt);
  return motion;
}

TEST(RigidBody, ForceModesScaleByMassAndTimeAsDocumented) {
  BodyDefinition definition = sphereBody();
  definition.mass = 4.0;
  definition.useGravity = false;
  const double dt = 0.1;
  const auto velocityAfter = [&](ForceMode mode) {
    RigidBody body(definition);
    body.addForce(Vec3(8, 0, 0), mode);
    return velocityHalf(body, dt).linearVelocity.x();
  };
  EXPECT_DOUBLE_EQ(velocityAfter(ForceMode::Force), 8.0 / 4.0 * dt);
  EXPECT_DOUBLE_EQ(velocityAfter(ForceMode::Acceleration), 8.0 * dt);
  EXPECT_DOUBLE_EQ(velocityAfter(ForceMode::Impulse), 8.0 / 4.0);
  EXPECT_DOUBLE_EQ(velocityAfter(ForceMode::VelocityChange), 8.0);

  RigidBody body(definition);
  body.addTorque(Vec3(0, 0, 1), ForceMode::Impulse);
  // Sphere of radius 0.5, mass 4: I = 2/5 m r^2 = 0.4.
  EXPECT_NEAR(velocityHalf(body, dt).angularVelocity.z(), 1.0 / 0.4, 1e-12);
}

TEST(RigidBody, StaticBodiesNeverMove) {
  World world;
  BodyDefinition definition = sphereBody();
  definition.isStatic = true;
  definition.position = Vec3(1, 2, 3);
  definition.linearVelocity = Vec3(5, 5, 5);
  const BodyId id = world.addBody(definition);
  world.body(id).addForce(Vec3(100, 0, 0), ForceMode::Impulse);
  for (int step = 0; step < 10; ++step) world.step();
  EXPECT_EQ(world.body(id).position(), Vec3(1, 2, 3));
  EXPECT_EQ(world.body(id).linearVelocity(), Vec3::Zero());
}

TEST(RigidBody, LockedAxesKeepTheirInitialValue) {
  World world;
  BodyDefinition definition = sphereBody();
  definition.position = Vec3(0.3, 5, -0.7);
  definition.linearVelocity = Vec3(1, 1, 1);
  definition.angularVelocity = Vec3(1, 1, 1);
  definition.lockTranslation = {false, true, false};
  definition.lockRotation = {true, false, true};
  const BodyId id = world.addBody(definition);
  world.body(id).addForce(Vec3(0, 50, 0), ForceMode::Impulse);
  world.body(id).addTorque(Vec3(3, 0, 3), ForceMode::Impulse);
  for (int step = 0; step < 100; ++step) world.step();
  EXPECT_EQ(world.body(id).position().y(), 5.0);
  EXPECT_EQ(world.body(id).angularVelocity().x(), 0.0);
  EXPECT_EQ(world.body(id).angularVelocity().z(), 0.0);
  EXPECT_NE(world.body(id).position().x(), 0.3);
}

TEST(RigidBody, TumblingBoxKeepsEnergyAndAngularMomentum) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.dt = 0.01;
  World world(settings);
  BodyDefinition definition;
  definition.collider = std::make_shared<BoxCollider>(Vec3(0.1, 0.2, 0.3));
  definition.angularVelocity = Vec3(1, 2, 3);
  const BodyId id = world.addBody(definition);
  const double energy = world.body(id).kineticEnergy();
  const Vec3 momentum = world.body(id).angularMomentum();
  double largestEnergy = energy;
  for (int step = 0; step < 500; ++step) {
    world.step();
    largestEnergy = std::max(largestEnergy, world.body(id).kineticEnergy());
  }
  EXPECT_LE(largestEnergy, energy * (1 + 1e-6));
  EXPECT_LT((world.body(id).angularMomentum() - momentum).norm(), 1e-3 * momentum.norm());
}

TEST(RigidBody, RejectsBadDefinitions) {
  BodyDefinition definition = sphereBody();
  definition.mass = 0;
  EXPECT_THROW(RigidBody{definition}, std::invalid_argument);
  definition.mass = 1;
  definition.linearVelocity.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RigidBody{definition}, std::invalid_argument);
  BodyDefinition noCollider;
  EXPECT_THROW(RigidBody{noCollider}, std::invalid_argument);
}

TEST(World, NonFiniteBodyIsReportedAndFrozenWithoutPoisoningOthers) {
  World world;
  const BodyId good = world.addBody(sphereBody());
  const BodyId bad = world.addBody(sphereBody());
  world.step();
  world.body(bad).setLinearVelocity(Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  for (int step = 0; step < 10; ++step) world.step();
  ASSERT_EQ(world.numericalFaults().size(), 1u);
  EXPECT_EQ(world.numericalFaults()[0].body, bad);
  EXPECT_EQ(world.numericalFaults()[0].step, 2);
  EXPECT_TRUE(world.isFrozen(bad));
  EXPECT_FALSE(world.isFrozen(good));
  EXPECT_TRUE(world.body(good).hasFiniteState());
}

}  // namespace
}  // namespace physdbg
