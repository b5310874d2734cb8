// Free fall, constant forces and torques, and drag, against the closed forms
// of the engine's integrator: semi-implicit Euler on every substep (h = dt /
// substeps; a body in no manifold takes flightSubstepCount's, which is
// solver.substeps up to 1/30 s steps), so after N substeps
// x = x0 + v0 N h + a h^2 N (N + 1) / 2 and v = v0 + a N h. Cases from Jolt's
// UnitTests/Physics/PhysicsTests.cpp; drag follows Box2D v3's law (no peer
// unit test covers drag).
#include <cmath>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// Jolt PhysicsTests.cpp::TestPhysicsFreeFall: a 2 m box falls from y = 10 for
// 2 s at 1, 2 and 4 steps per 1/60 s. Jolt: velocity g t within 1e-4 (float),
// position against its own Euler prediction within 1e-6 m. Ours: the same two
// answers (the engine's substeps in the prediction), velocity within 1e-11
// m/s and position within 1e-10 m: doubles, 960 additions at most, so
// rounding stays below 1e-12 of the 20 m/s and 20 m involved.
TEST(PeerFreeFall, BoxFollowsSemiImplicitEulerAtThreeStepLengths) {
  const double duration = 2.0;
  double worstPosition = 0.0, worstVelocity = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    SCOPED_TRACE(dt);
    World world(settings(dt));
    const BodyId id = world.addBody(box(Vec3::Ones(), Vec3(0, 10, 0), 8000.0));
    const int steps = static_cast<int>(std::lround(duration / dt));
    stepN(world, steps);
    const double h = substep(world.settings());
    const long substeps = static_cast<long>(steps) * flightSubsteps(world.settings());
    const RigidBody& body = world.body(id);
    const double expectedY = eulerPosition(10.0, 0.0, -kGravity, h, substeps);
    EXPECT_NEAR(body.linearVelocity().y(), -kGravity * duration, 1e-11);
    EXPECT_NEAR(body.position().y(), expectedY, 1e-10);
    EXPECT_EQ(body.position().x(), 0.0);
    EXPECT_EQ(body.position().z(), 0.0);
    EXPECT_EQ(body.angularVelocity(), Vec3::Zero());
    worstPosition = std::max(worstPosition, std::abs(body.position().y() - expectedY));
    worstVelocity = std::max(worstVelocity, std::abs(body.linearVelocity().y() + kGravity * duration));
  }
  measured("worst_position_error_m", worstPosition);
  measured("worst_velocity_error_mps", worstVelocity);
}

// Jolt PhysicsTests.cpp::TestPhysicsTestContext checks that its Euler
// prediction lies within 0.2 m of the parabola x0 + g t^2 / 2 after 2 s.
// Replaced by the exact offset: semi-implicit Euler falls g h t / 2 further
// than the parabola (h the substep). Ours: that offset within 1e-10 m.
TEST(PeerFreeFall, OffsetFromTheParabolaIsHalfASubstepOfSpeed) {
  const double dt = 1.0 / 60.0, duration = 2.0;
  World world(settings(dt));
  const BodyId id = world.addBody(box(Vec3::Ones(), Vec3(0, 10, 0), 8000.0));
  stepN(world, 120);
  const double h = substep(world.settings());
  const double parabola = 10.0 - 0.5 * kGravity * duration * duration;
  const double offset = world.body(id).position().y() - parabola;
  measured("offset_m", offset);
  EXPECT_NEAR(offset, -0.5 * kGravity * h * duration, 1e-10);
  EXPECT_LT(std::abs(offset), 0.2);  // Jolt's own bound, for the record
}

// Jolt PhysicsTests.cpp::TestPhysicsApplyForce: a force m a (a = 2 m/s^2
// along x) every step for 2 s, with gravity. Jolt: velocity (g + a) t within
// 1e-4, position against its Euler prediction within 1e-6 m. Ours: 1e-11 m/s
// and 1e-10 m, as in the free fall (the force is spread evenly over the
// substeps: RigidBody::beginStep makes it the step's acceleration).
TEST(PeerForces, ConstantForceAcceleratesAlongsideGravity) {
  const double acceleration = 2.0, duration = 2.0, mass = 8000.0;
  double worst = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    SCOPED_TRACE(dt);
    World world(settings(dt));
    const BodyId id = world.addBody(box(Vec3::Ones(), Vec3(0, 10, 0), mass));
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int i = 0; i < steps; ++i) {
      world.body(id).addForce(Vec3(mass * acceleration, 0, 0));
      world.step();
    }
    const double h = substep(world.settings());
    const long n = static_cast<long>(steps) * flightSubsteps(world.settings());
    const RigidBody& body = world.body(id);
    EXPECT_NEAR(body.linearVelocity().x(), acceleration * duration, 1e-11);
    EXPECT_NEAR(body.linearVelocity().y(), -kGravity * duration, 1e-11);
    EXPECT_NEAR(body.position().x(), eulerPosition(0.0, 0.0, acceleration, h, n), 1e-10);
    EXPECT_NEAR(body.position().y(), eulerPosition(10.0, 0.0, -kGravity, h, n), 1e-10);
    worst = std::max(worst, std::abs(body.position().x() - eulerPosition(0.0, 0.0, acceleration, h, n)));
  }
  measured("worst_x_error_m", worst);
}

// Jolt PhysicsTests.cpp::TestPhysicsApplyTorque: a torque I alpha (alpha = 2
// rad/s^2 about y) on a 2 m cube (I = m 8/12) for 2 s. Jolt: angular velocity
// alpha t within 1e-4, orientation against its Euler prediction within 1e-4.
// Ours: the same answers, angular velocity within 1e-11 rad/s and orientation
// within 1e-10 rad: each substep turns the cube by w h about the fixed y axis,
// exactly (rotationFromVector), so the angle is alpha h^2 N (N + 1) / 2.
TEST(PeerForces, ConstantTorqueSpinsUpACubeAboutAFixedAxis) {
  const double alpha = 2.0, duration = 2.0, mass = 8000.0;
  const double inertia = mass * 8.0 / 12.0;
  double worst = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    SCOPED_TRACE(dt);
    WorldSettings s = settings(dt);
    s.gravity = Vec3::Zero();
    World world(s);
    const BodyId id = world.addBody(box(Vec3::Ones(), Vec3(0, 10, 0), mass));
    EXPECT_NEAR(world.body(id).localInertia()(1, 1), inertia, 1e-9);
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int i = 0; i < steps; ++i) {
      world.body(id).addTorque(Vec3(0, inertia * alpha, 0));
      world.step();
    }
    const double h = substep(world.settings());
    const long n = static_cast<long>(steps) * flightSubsteps(world.settings());
    const double angle = eulerPosition(0.0, 0.0, alpha, h, n);
    const RigidBody& body = world.body(id);
    EXPECT_NEAR(body.angularVelocity().y(), alpha * duration, 1e-11);
    EXPECT_EQ(body.angularVelocity().x(), 0.0);
    EXPECT_EQ(body.angularVelocity().z(), 0.0);
    const double error = angleBetween(body.orientation(), Quat(Eigen::AngleAxisd(angle, Vec3::UnitY())));
    EXPECT_LT(error, 1e-10);
    worst = std::max(worst, error);
  }
  measured("worst_orientation_error_rad", worst);
}

// Jolt PhysicsTests.cpp::TestPhysicsCollisionElastic<GravityThroughAddForce =
// true>: gravity switched off and applied as a force every step must give
// the run that gravity gives, bounce included (Jolt checks both runs against
// the same tolerances). Ours: the two runs agree bit for bit, step by step
// (a force of m g on a 1 kg ball is exactly g as an acceleration).
TEST(PeerForces, GravityAppliedAsAForceGivesTheSameRunBitForBit) {
  const auto run = [](bool throughForce) {
    World world(settings());
    world.addBody(floorSlab());
    BodyDefinition ball = sphere(1.0, Vec3(0, 5.0, 0), 1.0, material(1.0, 0.6));
    ball.useGravity = !throughForce;
    const BodyId id = world.addBody(ball);
    std::vector<double> trace;
    for (int i = 0; i < 180; ++i) {
      if (throughForce) world.body(id).addForce(Vec3(0, -kGravity, 0));
      world.step();
      trace.push_back(world.body(id).position().y());
      trace.push_back(world.body(id).linearVelocity().y());
    }
    return trace;
  };
  const std::vector<double> gravity = run(false), force = run(true);
  ASSERT_EQ(gravity.size(), force.size());
  int differing = 0;
  for (std::size_t i = 0; i < gravity.size(); ++i) differing += gravity[i] != force[i];
  measured("differing_values", differing);
  EXPECT_EQ(differing, 0);
  // It bounced: the ball went up again at some point.
  bool rose = false;
  for (std::size_t i = 1; i < gravity.size(); i += 2) rose = rose || gravity[i] > 0.0;
  EXPECT_TRUE(rose);
}

// Drag. No peer unit test covers it; the law is Box2D v3's
// (b2IntegrateVelocitiesTask: v = v / (1 + h c) on each substep), which is
// physdbg's (motion.h). After N substeps without other forces v = v0 / (1 +
// c h)^N and x = v0 h sum_k (1 + c h)^-k. Ours: both within 1e-12 relative
// (rounding), and the distance from the continuous answer v0 exp(-c t) is
// the method's, at most v0 c^2 h t / 2 (ln(1 + c h) = c h - (c h)^2 / 2 +
// ...), and positive.
TEST(PeerDamping, LinearDragDividesTheVelocityOnEverySubstep) {
  const double drag = 0.5, v0 = 10.0, duration = 2.0;
  World world(weightless());
  BodyDefinition body = box(Vec3::Constant(0.5), Vec3::Zero());
  body.linearDrag = drag;
  body.linearVelocity = Vec3(v0, 0, 0);
  const BodyId id = world.addBody(body);
  stepN(world, 120);
  const double h = substep(world.settings());
  const long n = 120L * flightSubsteps(world.settings());
  const double q = 1.0 / (1.0 + drag * h);
  const double expectedV = v0 * std::pow(q, static_cast<double>(n));
  const double expectedX = v0 * h * q * (1.0 - std::pow(q, static_cast<double>(n))) / (1.0 - q);
  const RigidBody& b = world.body(id);
  EXPECT_NEAR(b.linearVelocity().x(), expectedV, 1e-12 * v0);
  EXPECT_NEAR(b.position().x(), expectedX, 1e-12 * expectedX);
  const double continuous = v0 * std::exp(-drag * duration);
  const double methodError = (b.linearVelocity().x() - continuous) / v0;
  measured("relative_error_vs_exp", methodError);
  EXPECT_GT(methodError, 0.0);
  EXPECT_LE(methodError, 0.5 * drag * drag * h * duration * 1.01);
}

// The same law for the angular velocity (angular_drag), on a sphere (no
// gyroscopic term). Ours: 1e-12 relative.
TEST(PeerDamping, AngularDragDividesTheSpinOnEverySubstep) {
  const double drag = 1.5, w0 = 20.0;
  World world(weightless());
  BodyDefinition body = sphere(0.5, Vec3::Zero());
  body.angularDrag = drag;
  body.angularVelocity = Vec3(0, 0, w0);
  const BodyId id = world.addBody(body);
  stepN(world, 90);
  const long n = 90L * flightSubsteps(world.settings());
  const double expected = w0 * std::pow(1.0 + drag * substep(world.settings()), -static_cast<double>(n));
  measured("spin_rad_s", world.body(id).angularVelocity().z());
  EXPECT_NEAR(world.body(id).angularVelocity().z(), expected, 1e-12 * w0);
  EXPECT_EQ(world.body(id).linearVelocity(), Vec3::Zero());
}

// Drag against gravity: v_{k+1} = (v_k + g h) / (1 + c h) has the fixed point
// v = g / c exactly (the continuous terminal speed, whatever h), reached
// geometrically. After 20 s with c = 2 the remaining factor is e^-40. Ours:
// g / c within 1e-12 relative.
TEST(PeerDamping, DragAndGravityGiveTheExactTerminalSpeed) {
  const double drag = 2.0;
  World world(settings());
  BodyDefinition body = sphere(0.5, Vec3(0, 1000, 0));
  body.linearDrag = drag;
  const BodyId id = world.addBody(body);
  stepN(world, 1200);
  const double terminal = kGravity / drag;
  measured("terminal_speed_mps", -world.body(id).linearVelocity().y());
  EXPECT_NEAR(-world.body(id).linearVelocity().y(), terminal, 1e-12 * terminal);
}

}  // namespace
}  // namespace physdbg::peers
