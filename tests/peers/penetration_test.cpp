// Penetration recovery: bodies that start inside the floor or inside each
// other are pushed out to where a resting contact sits, without being thrown
// and without gaining energy; and the overlap the narrow phase measures
// between two spheres. Cases from Jolt's UnitTests/Physics/PhysicsTests.cpp
// (TestPhysicsPenetrationSlop1, 2, 3), Box2D v3's test/test_restitution.c
// (the soft contact's lift in EnergyTest and OvershootTest), Jolt's
// ContactListenerTests.cpp (two overlapping spheres) and Bullet's
// test/collision/main.cpp (sphere-sphere distance). Jolt leaves up to its
// slop (0.02 m) of overlap in place; physdbg's soft contact settles every
// resting contact at the depth its load gives, g / (2 pi f)^2 (0.07 mm at
// 60 Hz), which replaces the slop in the expectations.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/narrowphase/narrow_phase.h"
#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// The depth a contact settles at under the weight of what rests on it: g /
// omega^2 for the frequency the island's contacts used in the last step
// (contactHertz, or a quarter of the substep rate when that is lower: at 4
// calm substeps and dt = 4/60 s, 15 Hz and 1.1 mm).
double restingDepth(const World& world) {
  const double omega = 2.0 * std::numbers::pi * world.lastStepStats().contactHertz;
  return kGravity / (omega * omega);
}

// A box of half extent 1 started `overlap` into Jolt's floor, stepped for
// 1 s at `dt`; returns it, and the highest it rose relative to the surface.
struct Settled {
  World world;
  BodyId box = 0;
  double highest = -1.0;
};

Settled settleFromOverlap(double dt, double overlap) {
  Settled run{World(settings(dt)), 0, -1.0};
  run.world.addBody(floorSlab());
  run.box = run.world.addBody(box(Vec3::Ones(), Vec3(0, 1.0 - overlap, 0)));
  const int steps = static_cast<int>(std::lround(1.0 / dt));
  for (int i = 0; i < steps; ++i) {
    run.world.step();
    run.highest = std::max(run.highest, run.world.body(run.box).position().y() - 1.0);
  }
  return run;
}

// Settles a box from each of Jolt's three overlaps at `dt`; returns the worst
// distance from the resting depth after 1 s, and checks it never rose above
// the surface (1e-9 m).
double worstSettlingError(double dt, double& highest) {
  double worst = 0.0;
  for (const double overlap : {0.02, 0.04, 0.002}) {
    SCOPED_TRACE(overlap);
    Settled run = settleFromOverlap(dt, overlap);
    worst = std::max(worst, std::abs(run.world.body(run.box).position().y() - (1.0 - restingDepth(run.world))));
    EXPECT_LE(run.highest, 1e-9);
    highest = std::max(highest, run.highest);
  }
  return worst;
}

// Jolt PhysicsTests.cpp::TestPhysicsPenetrationSlop1, 2 and 3, at 1, 2 and 4
// steps per 1/60 s: a box of half extent 1 starting 1, 2 and 0.1 slops (2,
// 4 and 0.2 cm) into the floor. Jolt: after 1 s it rests at 1 slop deep (or
// where it started when less), within 1e-5 m, with no velocity (1e-6).
// Here its height: at the resting depth within 1e-6 m and never above the
// surface on the way (1e-9 m): recovery is not a launch. The soft contact
// is overdamped (damping ratio 5): its slow mode decays at omega (5 -
// sqrt(24)), a time constant of 0.026 s at 60 Hz and 0.105 s at 15 Hz, so
// after 1 s a 4 cm overlap has at most 3e-6 m left. Jolt's 1/60 and 2/60 s
// steps here (60 and 30 Hz), its 4/60 s step below.
TEST(PeerPenetration, OverlapWithTheFloorSettlesAtTheRestingDepth) {
  double worst = 0.0, highest = -1.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0}) {
    SCOPED_TRACE(dt);
    const double error = worstSettlingError(dt, highest);
    EXPECT_LT(error, 1e-6);
    worst = std::max(worst, error);
  }
  measured("worst_depth_error_m", worst);
  measured("highest_above_surface_m", highest);
}

// The same at 4/60 s, where the calm box's contact softens to 15 Hz.
// Fails today: 9.9e-6 m of the overlap is left after 1 s, within Jolt's
// 1e-5 m but beyond the 3e-6 m the contact's own time constant allows (1.3e-5
// m before deep faces were pushed out at all their points at once).
TEST(PeerPenetration, DISABLED_OverlapWithTheFloorSettlesAtTheRestingDepthWithLongSteps) {
  double highest = -1.0;
  const double error = worstSettlingError(4.0 / 60.0, highest);
  measured("worst_depth_error_m", error);
  EXPECT_LT(error, 1e-6);
}

// The same runs, Jolt's other checks: the box is pushed straight out (its
// position is checked whole, within 1e-5 m) and ends without velocity
// (1e-6). Ours: x and z unchanged within 1e-6 m, speed below 1e-7 m/s and
// spin below 1e-7 rad/s.
// Fails today: the box walks sideways by up to 7.0e-5 m while it is pushed
// out, and still moves at 1.2e-5 m/s after 1 s. A face sunk deeper than the
// slop is pushed out at all its points at once (straight up); the last 5 mm
// go point by point, where Gauss-Seidel over the four corners tilts the box
// a little and its corners slide. (5.3e-4 m and 6.4e-5 m/s when the whole
// push-out went point by point.)
TEST(PeerPenetration, DISABLED_OverlapWithTheFloorIsPushedStraightOutAndStops) {
  double worstDrift = 0.0, worstSpeed = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0})
    for (const double overlap : {0.02, 0.04, 0.002}) {
      SCOPED_TRACE(dt);
      SCOPED_TRACE(overlap);
      Settled run = settleFromOverlap(dt, overlap);
      const RigidBody& body = run.world.body(run.box);
      const double drift = std::hypot(body.position().x(), body.position().z());
      EXPECT_LT(drift, 1e-6);
      EXPECT_LT(body.linearVelocity().norm(), 1e-7);
      EXPECT_LT(body.angularVelocity().norm(), 1e-7);
      worstDrift = std::max(worstDrift, drift);
      worstSpeed = std::max({worstSpeed, body.linearVelocity().norm(), body.angularVelocity().norm()});
    }
  measured("worst_sideways_drift_m", worstDrift);
  measured("worst_speed", worstSpeed);
}

// Box2D test_restitution.c::EnergyTest and ::OvershootTest name the soft
// contact's lift of a body that starts deep in the ground as "potential
// energy from nowhere" and allow 2% of the energy for it (discrete). A unit
// box starting a quarter of its size (0.25 m) into the floor: the push-out
// may cost energy but the box must not be thrown: it never rises above the
// surface, never moves up faster than the push limit (maxPushSpeed, 3 m/s),
// and ends at the resting depth. Ours: above the surface by at most 1e-9 m
// (no energy beyond m g times the overlap), speed within 3 m/s, at the
// resting depth within 1e-6 m after 2 s.
TEST(PeerPenetration, DeepOverlapIsPushedOutWithoutThrowingTheBody) {
  World world(settings());
  world.addBody(floorSlab());
  const BodyId id = world.addBody(box(Vec3::Constant(0.5), Vec3(0, 0.25, 0)));
  double highest = -1.0, fastest = 0.0;
  for (int i = 0; i < 120; ++i) {
    world.step();
    highest = std::max(highest, world.body(id).position().y() - 0.5);
    fastest = std::max(fastest, world.body(id).linearVelocity().y());
  }
  measured("highest_above_surface_m", highest);
  measured("fastest_up_mps", fastest);
  EXPECT_LE(highest, 1e-9);
  EXPECT_LE(fastest, world.settings().solver.maxPushSpeed);
  EXPECT_NEAR(world.body(id).position().y(), 0.5 - restingDepth(world), 1e-6);
}

// Jolt ContactListenerTests.cpp::TestCollideKinematicVsNonDynamic starts two
// radius-1 spheres 1 m into each other; with both dynamic, no gravity, they
// are pushed apart. The analytic answers: no momentum is made (the push is
// internal), the two move symmetrically, and the push ends with them apart
// and at rest. No peer tolerance on these (Jolt checks that velocities
// changed). Ours: momentum below 1e-15 kg m/s, positions symmetric within
// 1e-12 m, after 2 s no overlap beyond 1e-6 m and speeds below 1e-6 m/s.
TEST(PeerPenetration, OverlappingBallsArePushedApartWithoutMakingMomentum) {
  World world(weightless());
  const BodyId a = world.addBody(sphere(1.0, Vec3(-0.5, 0, 0)));
  const BodyId b = world.addBody(sphere(1.0, Vec3(0.5, 0, 0)));
  double worstMomentum = 0.0, worstAsymmetry = 0.0;
  for (int i = 0; i < 120; ++i) {
    world.step();
    worstMomentum = std::max(worstMomentum, (world.body(a).linearVelocity() + world.body(b).linearVelocity()).norm());
    worstAsymmetry = std::max(worstAsymmetry, (world.body(a).position() + world.body(b).position()).norm());
  }
  const double gap = world.body(b).position().x() - world.body(a).position().x() - 2.0;
  const double speed = std::max(world.body(a).linearVelocity().norm(), world.body(b).linearVelocity().norm());
  measured("worst_momentum_kg_mps", worstMomentum);
  measured("final_gap_m", gap);
  measured("final_speed_mps", speed);
  EXPECT_LT(worstMomentum, 1e-15);
  EXPECT_LT(worstAsymmetry, 1e-12);
  EXPECT_GT(gap, -1e-6);
  EXPECT_LT(speed, 1e-6);
}

// Bullet test/collision/main.cpp::AnalyticSphereSphereDistance (and the
// GJK/EPA variants): spheres of radius 1 to 4 and 0.1 to 0.4 with centres
// on the y axis at integer heights -5..4 (concentric pairs skipped):
// distance |i - z| - ra - rb within 1e-5 (1e-4 for GJK/MPR), and the point
// on A equal to the point on B moved by the distance along the normal.
// Ours, through the engine's narrow phase: the signed distance (distance,
// or minus the depth) within 1e-12 m, the points consistent within 1e-12 m.
TEST(PeerPenetration, SphereSphereDistanceAndDepthAreExact) {
  double worst = 0.0;
  int pairs = 0;
  for (int rb = 1; rb < 5; ++rb)
    for (int z = -5; z < 5; ++z)
      for (int j = 1; j < 5; ++j)
        for (int i = -5; i < 5; ++i) {
          if (i == z) continue;
          const SphereCollider sphereA(j), sphereB(0.1 * rb);
          const Transform ta{Vec3(0, i, 0), Quat::Identity()}, tb{Vec3(0, z, 0), Quat::Identity()};
          const ContactResult result = collide(sphereA, ta, sphereB, tb, NarrowPhaseOptions{});
          const double expected = std::abs(i - z) - j - 0.1 * rb;
          const double signedDistance = result.status == ContactStatus::Separated ? result.distance : -result.depth;
          const double error = std::abs(signedDistance - expected);
          // pointB = pointA + normal * signed distance (normal from A to B).
          const double consistency = (result.pointA + result.normal * signedDistance - result.pointB).norm();
          EXPECT_LT(error, 1e-12) << "i " << i << " z " << z << " j " << j << " rb " << rb;
          EXPECT_LT(consistency, 1e-12) << "i " << i << " z " << z << " j " << j << " rb " << rb;
          worst = std::max({worst, error, consistency});
          ++pairs;
        }
  measured("pairs", pairs);
  measured("worst_error_m", worst);
}

}  // namespace
}  // namespace physdbg::peers
