// Axis locks (Jolt's allowed degrees of freedom): locked coordinates stay
// exactly where they were, free ones respond as the constrained body does,
// and a body that cannot move into a contact is not stopped by it. Cases from
// Jolt's UnitTests/Physics/PhysicsTests.cpp (TestAllowedDOFs,
// TestAllowedDOFsVsCollision). Jolt expects the angular response
// S I^-1 S (inverse inertia with the locked rows and columns cleared); the
// constrained body's answer is B (B^T I B)^-1 B^T, B the free axes, which is
// what these cases expect (they agree when the world inertia is diagonal).
#include <cmath>
#include <numbers>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

const Vec3 kHalfExtents(0.3, 0.5, 0.7);  // Jolt's box, density 1000: 840 kg
constexpr double kMass = 840.0;

Quat joltRotation() { return Quat(Eigen::AngleAxisd(20.0 * std::numbers::pi / 180.0, Vec3::Ones().normalized())); }

BodyDefinition joltBox(std::array<bool, 3> lockTranslation, std::array<bool, 3> lockRotation) {
  BodyDefinition def = box(kHalfExtents, Vec3(1, 2, 3), kMass);
  def.orientation = joltRotation();
  def.lockTranslation = lockTranslation;
  def.lockRotation = lockRotation;
  return def;
}

std::array<bool, 3> mask(int bits) { return {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0}; }

// The world inertia of a body and the constrained angular response to an
// angular impulse with the rotations of `locked` removed: B (B^T I B)^-1 B^T.
Mat3 constrainedResponse(const Mat3& worldInertia, std::array<bool, 3> locked) {
  int free = 0;
  for (bool l : locked) free += l ? 0 : 1;
  if (free == 0) return Mat3::Zero();
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3, free);
  for (int axis = 0, column = 0; axis < 3; ++axis)
    if (!locked[axis]) basis(axis, column++) = 1.0;
  const Eigen::MatrixXd reduced = basis.transpose() * worldInertia * basis;
  return basis * reduced.inverse() * basis.transpose();
}

Mat3 worldInertia(const RigidBody& body) {
  const Mat3 rotation = body.orientation().toRotationMatrix();
  return rotation * body.localInertia() * rotation.transpose();
}

// Jolt PhysicsTests.cpp::TestAllowedDOFs, its linear half: a force of (1e5,
// 1.1e5, 1.2e5) N on Jolt's 840 kg box for one step, under every combination
// of translation locks. Jolt: velocity lock(F / m dt) and position p0 + v dt
// within 1e-6 (its one Euler step). Ours: velocity within 1e-12 of F / m dt
// on the free axes and exactly 0 on locked ones; free coordinates on the
// substep Euler path within 1e-12 m, locked ones exactly (==) unchanged.
TEST(PeerAxisLocks, LockedTranslationAxesKeepTheirCoordinateExactly) {
  const Vec3 force(100000, 110000, 120000);
  double worst = 0.0;
  for (int bits = 0; bits < 8; ++bits) {
    SCOPED_TRACE(bits);
    World world(weightless());
    const BodyId id = world.addBody(joltBox(mask(bits), {false, false, false}));
    const Vec3 start = world.body(id).position();
    world.body(id).addForce(force);
    world.step();
    const RigidBody& body = world.body(id);
    const double h = substep(world.settings());
    const long n = flightSubsteps(world.settings());
    for (int axis = 0; axis < 3; ++axis) {
      if (mask(bits)[axis]) {
        EXPECT_EQ(body.linearVelocity()[axis], 0.0) << "axis " << axis;
        EXPECT_EQ(body.position()[axis], start[axis]) << "axis " << axis;
        continue;
      }
      const double a = force[axis] / kMass;
      EXPECT_NEAR(body.linearVelocity()[axis], a * world.settings().dt, 1e-12) << "axis " << axis;
      EXPECT_NEAR(body.position()[axis], eulerPosition(start[axis], 0.0, a, h, n), 1e-12) << "axis " << axis;
      worst = std::max(worst, std::abs(body.linearVelocity()[axis] - a * world.settings().dt));
    }
  }
  measured("worst_velocity_error_mps", worst);
}

// TestAllowedDOFs' angular half with every rotation free, as an angular
// impulse (13000, 14000, 15000) N m s applied at once. Jolt expects the spin
// I^-1 tau dt after the step, which leaves out the gyroscopic motion (Jolt
// applies none by default); at 90 rad/s the box turns 1.5 rad in the step,
// so the engine-neutral answer is the free body's: its world angular
// momentum stays L and its kinetic energy L^T I^-1 L / 2, for the whole
// second it tumbles. Jolt: 1e-6 against its model. Ours: momentum within
// 1e-12 relative and energy within 1e-9 relative (the implicit midpoint rule
// keeps both, motion.cpp).
TEST(PeerAxisLocks, FreeBodyKeepsItsAngularMomentumAndEnergyWhileTumbling) {
  const Vec3 impulse(13000, 14000, 15000);
  World world(weightless());
  const BodyId id = world.addBody(joltBox({false, false, false}, {false, false, false}));
  const double energy = 0.5 * impulse.dot(worldInertia(world.body(id)).inverse() * impulse);
  world.body(id).addTorque(impulse, ForceMode::Impulse);
  double worstMomentum = 0.0, worstEnergy = 0.0;
  for (int i = 0; i < 60; ++i) {
    world.step();
    worstMomentum = std::max(worstMomentum, (world.body(id).angularMomentum() - impulse).norm() / impulse.norm());
    worstEnergy = std::max(worstEnergy, std::abs(world.body(id).kineticEnergy() - energy) / energy);
  }
  measured("worst_momentum_error", worstMomentum);
  measured("worst_energy_error", worstEnergy);
  EXPECT_LT(worstMomentum, 1e-12);
  EXPECT_LT(worstEnergy, 1e-9);
}

// TestAllowedDOFs with all three rotations locked: Jolt expects the initial
// rotation (1e-6). Ours: the orientation unchanged bit for bit and no spin.
TEST(PeerAxisLocks, AllRotationsLockedKeepTheOrientationExactly) {
  World world(weightless());
  const BodyId id = world.addBody(joltBox({false, false, false}, {true, true, true}));
  const Quat start = world.body(id).orientation();
  world.body(id).addTorque(Vec3(13000, 14000, 15000));
  world.body(id).addForceAtPoint(Vec3(0, 1000, 0), Vec3(2, 2, 3));
  stepN(world, 10);
  EXPECT_EQ(world.body(id).orientation().coeffs(), start.coeffs());
  EXPECT_EQ(world.body(id).angularVelocity(), Vec3::Zero());
  measured("spin_rad_s", world.body(id).angularVelocity().norm());
}

// TestAllowedDOFs under every rotation lock but all three, as the response to
// an angular impulse: the constrained B (B^T I B)^-1 B^T L, not Jolt's
// S I^-1 S L, which is what a body held by bearings does (the bearings push
// back along the locked axes, changing the free spin too when the world
// inertia has products of inertia). The impulse is 1e-12 of Jolt's so that
// the body turns by 1e-12 rad in the step and the response is read at the
// pose it was computed for. Jolt: 1e-6 against its model. Ours: 1e-9
// relative, locked components exactly 0.
TEST(PeerAxisLocks, PartlyLockedBodyGetsTheConstrainedAngularResponse) {
  const Vec3 impulse = Vec3(13000, 14000, 15000) * 1e-12;
  double worst = 0.0;
  for (int bits = 0; bits < 7; ++bits) {
    SCOPED_TRACE(bits);
    World world(weightless());
    const BodyId id = world.addBody(joltBox({false, false, false}, mask(bits)));
    const Vec3 expected = constrainedResponse(worldInertia(world.body(id)), mask(bits)) * impulse;
    world.body(id).addTorque(impulse, ForceMode::Impulse);
    world.step();
    const double error = (world.body(id).angularVelocity() - expected).norm() / expected.norm();
    EXPECT_LT(error, 1e-9);
    for (int axis = 0; axis < 3; ++axis)
      if (mask(bits)[axis]) {
        EXPECT_EQ(world.body(id).angularVelocity()[axis], 0.0);
      }
    worst = std::max(worst, error);
  }
  measured("worst_relative_error", worst);
}

// The same partly locked bodies with Jolt's full impulse, followed for a
// second. The bearings' torque lies along the locked axes, so it changes
// neither the angular momentum about the free axes (B^T L) nor the energy
// (it does no work): both stay at their values after the impulse while the
// body turns and its world inertia with it. No peer tolerance (Jolt reads
// one step). Ours: B^T L within 1e-9 relative, energy within 1e-9 relative.
// Fails today: the free momentum drifts by up to 0.466 of itself (the spin
// is kept constant while the body turns; the energy holds, 2e-15).
TEST(PeerAxisLocks, DISABLED_PartlyLockedBodyKeepsItsFreeMomentumAndEnergy) {
  const Vec3 impulse(13000, 14000, 15000);
  double worstMomentum = 0.0, worstEnergy = 0.0;
  for (int bits = 1; bits < 7; ++bits) {
    SCOPED_TRACE(bits);
    World world(weightless());
    const BodyId id = world.addBody(joltBox({false, false, false}, mask(bits)));
    const Mat3 response = constrainedResponse(worldInertia(world.body(id)), mask(bits));
    const Vec3 spin = response * impulse;
    const Vec3 freeMomentum = worldInertia(world.body(id)) * spin;  // its free components are B^T L
    const double energy = 0.5 * spin.dot(worldInertia(world.body(id)) * spin);
    world.body(id).addTorque(impulse, ForceMode::Impulse);
    for (int i = 0; i < 60; ++i) {
      world.step();
      const Vec3 momentum = world.body(id).angularMomentum();
      double error = 0.0;
      for (int axis = 0; axis < 3; ++axis)
        if (!mask(bits)[axis]) error = std::max(error, std::abs(momentum[axis] - freeMomentum[axis]));
      worstMomentum = std::max(worstMomentum, error / freeMomentum.norm());
      worstEnergy = std::max(worstEnergy, std::abs(world.body(id).kineticEnergy() - energy) / energy);
    }
  }
  measured("worst_free_momentum_error", worstMomentum);
  measured("worst_energy_error", worstEnergy);
  EXPECT_LT(worstMomentum, 1e-9);
  EXPECT_LT(worstEnergy, 1e-9);
}

// The torque case: rotation about x and y locked, a constant torque
// (13, 14, 15) N m for 1 s on Jolt's rotated box. Turning about the one free
// axis z leaves z^T I z unchanged, so the spin grows exactly as tau_z t /
// (z^T I z). No peer tolerance for this form (Jolt's TestAllowedDOFs is one
// step with S I^-1 S). Ours: 1e-12 relative.
TEST(PeerAxisLocks, TorqueAboutTheOneFreeAxisGivesTheConstrainedSpin) {
  const Vec3 torque(13, 14, 15);
  World world(weightless());
  const BodyId id = world.addBody(joltBox({false, false, false}, {true, true, false}));
  const double izz = worldInertia(world.body(id))(2, 2);
  for (int i = 0; i < 60; ++i) {
    world.body(id).addTorque(torque);
    world.step();
  }
  const double expected = torque.z() * 1.0 / izz;
  const double error = std::abs(world.body(id).angularVelocity().z() - expected) / expected;
  measured("spin_rad_s", world.body(id).angularVelocity().z());
  measured("expected_spin_rad_s", expected);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(world.body(id).angularVelocity().x(), 0.0);
  EXPECT_EQ(world.body(id).angularVelocity().y(), 0.0);
}

// Jolt PhysicsTests.cpp::TestAllowedDOFsVsCollision: a 1 kg box of half
// extent 1, free only to turn about y, 1 cm into a floor of friction 1 (its
// own 1), given a torque of 100 N m about y for one step. The contact cannot
// push it (no free motion along its normal), so it must not stop the spin:
// Jolt expects the contact added, the spin tau dt / I_yy (1e-6), no linear
// velocity and the position unchanged (==). Ours: spin within 1e-12
// relative, velocity and position bit for bit.
// Failed before the locks were rows of the solver: the spin after the step
// was 2.2327 rad/s against 2.5 (10.7% lost to friction from a contact that
// cannot be loaded).
TEST(PeerAxisLocks, ABodyThatCannotMoveIntoAContactIsNotStoppedByIt) {
  World world(settings());
  const BodyId floor = world.addBody(floorSlab(0.0, 100.0, material(0.0, 1.0)));
  BodyDefinition def = box(Vec3::Ones(), Vec3(0, 0.99, 0), 1.0, material(0.0, 1.0));
  def.lockTranslation = {true, true, true};
  def.lockRotation = {true, false, true};
  const BodyId id = world.addBody(def);
  RecordingListener events(world);
  world.body(id).addTorque(Vec3(0, 100, 0));
  world.step();
  EXPECT_EQ(events.count(RecordedEvent::Begin, floor, id), 1);
  const double expected = 100.0 * world.settings().dt / world.body(id).localInertia()(1, 1);
  const double error = std::abs(world.body(id).angularVelocity().y() - expected) / expected;
  measured("spin_rad_s", world.body(id).angularVelocity().y());
  measured("expected_spin_rad_s", expected);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(world.body(id).linearVelocity(), Vec3::Zero());
  EXPECT_EQ(world.body(id).position(), Vec3(0, 0.99, 0));
}

}  // namespace
}  // namespace physdbg::peers
