// Elastic and partial bounces, head-on impacts, restitution thresholds, flat
// and corner landings, Newton's cradle and resting piles with restitution.
// Cases from Jolt's UnitTests/Physics/PhysicsTests.cpp and
// MotionQualityLinearCastTests.cpp and Box2D v3's test/test_restitution.c.
// Heights are judged by the energy semi-implicit Euler keeps in flight,
// E = v^2/2 + g y - g h v/2 (peer_test_support.h): the apex of the discrete
// path is E/g to within g h^2/8, so "returns to its release height" is
// "leaves the floor with the E it arrived with".
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// Steps until the body has touched the floor and left it, rising and clear
// of every manifold (so in free flight, on the base substeps the energy is
// measured with); false if that did not happen within maxSteps.
bool stepUntilRisingClear(World& world, BodyId id, int maxSteps) {
  bool wentDown = false;
  for (int i = 0; i < maxSteps; ++i) {
    world.step();
    const RigidBody& body = world.body(id);
    if (body.linearVelocity().y() < 0.0) wentDown = true;
    if (wentDown && body.linearVelocity().y() > 0.0 && world.manifolds().empty()) return true;
  }
  return false;
}

// Steps until the body is falling again (its apex passed); returns the
// highest centre height seen.
double stepThroughApex(World& world, BodyId id, int maxSteps) {
  double highest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < maxSteps; ++i) {
    world.step();
    highest = std::max(highest, world.body(id).position().y());
    if (world.body(id).linearVelocity().y() <= 0.0) break;
  }
  return highest;
}

// Drops a radius-1 ball of restitution 1 from rest with its centre at
// `release` and returns the worst |E/g - release| over three bounces, E the
// flight energy once the ball is clear of the floor again (on the base
// substeps). Also checks no sampled centre rises above release + g h^2 / 8.
double elasticReturnError(double dt, double release) {
  World world(settings(dt));
  world.addBody(floorSlab());
  const BodyId id = world.addBody(sphere(1.0, Vec3(0, release, 0), 1.0, material(1.0, 0.6)));
  const double h = substep(world.settings());
  double worst = 0.0;
  for (int bounce = 0; bounce < 3; ++bounce) {
    SCOPED_TRACE(bounce);
    if (!stepUntilRisingClear(world, id, 600)) {
      ADD_FAILURE() << "no bounce " << bounce;
      return std::numeric_limits<double>::infinity();
    }
    const RigidBody& body = world.body(id);
    const double apex = flightEnergy(body.position().y(), body.linearVelocity().y(), kGravity, h) / kGravity;
    worst = std::max(worst, std::abs(apex - release));
    if (dt > 3.0 / 60.0) measured("apex_after_bounce_" + std::to_string(bounce + 1) + "_m", apex);
    const double highest = stepThroughApex(world, id, 600);
    EXPECT_LE(highest, release + kGravity * h * h / 8.0 + 1e-9);
  }
  return worst;
}

// Jolt PhysicsTests.cpp::TestPhysicsCollisionElastic (restitution 1, 1, 2
// and 4 steps per 1/60 s; back at the release point within 1e-5 m) and Box2D
// test_restitution.c::DropTest (six apexes, none above 1.001 of the drop).
// Jolt's exact position after the bounce step is its own integration order
// (bounce inside a substep); replaced by the height the energy gives: a
// ball of radius 1 released 5 m above the floor leaves with the E it
// arrived with. Ours: E/g within 1e-6 m of the release height on each of
// three bounces, and no sampled centre higher than it plus g h^2 / 8.
// Jolt's 1/60 and 2/60 s steps here; its 4/60 s step below.
TEST(PeerBounce, ElasticBallReturnsToItsReleaseHeight) {
  double worst = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0}) {
    SCOPED_TRACE(dt);
    const double error = elasticReturnError(dt, 6.0);
    EXPECT_LT(error, 1e-6);
    worst = std::max(worst, error);
  }
  measured("worst_apex_error_m", worst);
}

// The same at Jolt's third step length, 4/60 s. There a 60 Hz contact needs
// 16 substeps, so a body in flight takes 16 too (flightSubstepCount).
// Failed while the flight took 8 and the landing island 16: semi-implicit
// Euler keeps another energy for each h, and E/g after the bounces was
// 5.96165, 5.92358, 5.88687 m (0.113 m below the release height).
TEST(PeerBounce, ElasticBallReturnsToItsReleaseHeightWithLongSteps) {
  const double error = elasticReturnError(4.0 / 60.0, 6.0);
  measured("worst_apex_error_m", error);
  EXPECT_LT(error, 1e-6);
}

// Jolt PhysicsTests.cpp::TestPhysicsCollisionPartiallyElastic (restitution
// 0.9, radius 2 from y = 10; 1000 steps against its own bounce-in-one-step
// simulation within 1e-5) and Box2D test_restitution.c::PhaseTest (mean
// within 0.05 of e). Jolt's model ("reverse when within slop") is its own;
// replaced by the analytic law: each bounce leaves with e^2 of the energy it
// arrived with (measured from the height where the ball touches). Ours: the
// ratio of successive flight energies within 1e-6 of e^2, four bounces.
TEST(PeerBounce, PartialRestitutionKeepsESquaredOfTheEnergyEachBounce) {
  const double e = 0.9, radius = 2.0;
  World world(settings());
  world.addBody(floorSlab());
  const BodyId id = world.addBody(sphere(radius, Vec3(0, 10, 0), 1.0, material(e, 0.6)));
  const double h = substep(world.settings());
  double energy = kGravity * (10.0 - radius);  // at rest, gap 8 m
  double worst = 0.0;
  for (int bounce = 0; bounce < 4; ++bounce) {
    SCOPED_TRACE(bounce);
    ASSERT_TRUE(stepUntilRisingClear(world, id, 600));
    const RigidBody& body = world.body(id);
    const double next = flightEnergy(body.position().y() - radius, body.linearVelocity().y(), kGravity, h);
    EXPECT_NEAR(next / energy, e * e, 1e-6);
    worst = std::max(worst, std::abs(next / energy - e * e));
    energy = next;
  }
  measured("worst_ratio_error", worst);
}

// Box2D test_restitution.c::PhaseTest: no gravity, a ball driven at the
// ground at 5 m/s from 16 gaps spread over one step of travel, e = 0.25, 0.5
// and 0.9. Box2D: mean and spread of v_out / v_in within 0.05. Without a
// pull the analytic answer is e exactly at every phase. Ours: every sample
// within 1e-9 of e (rounding).
TEST(PeerBounce, CoefficientDoesNotDependOnWhereInTheStepTheImpactLands) {
  const double speed = 5.0, dt = 1.0 / 60.0;
  double worst = 0.0;
  for (const double e : {0.25, 0.5, 0.9}) {
    for (int i = 0; i < 16; ++i) {
      const double gap = (i / 16.0) * speed * dt;
      World world(weightless(dt));
      world.addBody(floorSlab(0.0, 40.0, material(0.0, 0.0)));
      BodyDefinition ball = sphere(0.5, Vec3(0, 0.5 + gap, 0), 1.0, material(e, 0.0));
      ball.linearVelocity = Vec3(0, -speed, 0);
      const BodyId id = world.addBody(ball);
      stepN(world, 60);
      const double ratio = world.body(id).linearVelocity().y() / speed;
      EXPECT_NEAR(ratio, e, 1e-9) << "e " << e << " gap " << gap;
      worst = std::max(worst, std::abs(ratio - e));
    }
  }
  measured("worst_ratio_error", worst);
}

// Box2D test_restitution.c::HeadOnTest: two free balls close head on at 5
// m/s, densities 1, 10 and 100 for the second, e from 0 to 1. Box2D: the
// ratio of relative speeds within 0.02 of e, momentum drift below 1e-4 of
// the total mass. Ours: 1e-9 and 1e-12 (the impulse law is exact).
TEST(PeerBounce, HeadOnRatioOfRelativeSpeedsIsTheCoefficient) {
  double worstRatio = 0.0, worstMomentum = 0.0;
  for (const double density : {1.0, 10.0, 100.0}) {
    for (const double e : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      World world(weightless());
      const double massA = 1.0, massB = density;
      BodyDefinition a = sphere(0.5, Vec3(-1, 0, 0), massA, material(e, 0.0));
      a.linearVelocity = Vec3(2.5, 0, 0);
      BodyDefinition b = sphere(0.5, Vec3(1, 0, 0), massB, material(e, 0.0));
      b.linearVelocity = Vec3(-2.5, 0, 0);
      const BodyId ia = world.addBody(a), ib = world.addBody(b);
      const double before = massA * 2.5 - massB * 2.5;
      stepN(world, 120);
      const double va = world.body(ia).linearVelocity().x(), vb = world.body(ib).linearVelocity().x();
      const double ratio = (vb - va) / 5.0;
      const double drift = (massA * va + massB * vb - before) / (massA + massB);
      EXPECT_NEAR(ratio, e, 1e-9) << "density " << density << " e " << e;
      EXPECT_NEAR(drift, 0.0, 1e-12) << "density " << density << " e " << e;
      worstRatio = std::max(worstRatio, std::abs(ratio - e));
      worstMomentum = std::max(worstMomentum, std::abs(drift));
    }
  }
  measured("worst_ratio_error", worstRatio);
  measured("worst_momentum_drift", worstMomentum);
}

// Jolt PhysicsTests.cpp::TestPhysicsCollisionElasticDynamic: two radius-1
// balls at x = -2 and 2, restitution 1, at 5 and -10 m/s, falling under
// gravity side by side for 1 s: they swap velocities and gravity along y is
// untouched (the contact is horizontal). Jolt: 1e-5. Ours: 1e-9 m/s.
TEST(PeerBounce, EqualMassBallsExchangeVelocitiesWhileFalling) {
  double worst = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    World world(settings(dt));
    BodyDefinition a = sphere(1.0, Vec3(-2, 0, 0), 1.0, material(1.0, 0.6));
    a.linearVelocity = Vec3(5, 0, 0);
    BodyDefinition b = sphere(1.0, Vec3(2, 0, 0), 1.0, material(1.0, 0.6));
    b.linearVelocity = Vec3(-10, 0, 0);
    const BodyId ia = world.addBody(a), ib = world.addBody(b);
    stepN(world, static_cast<int>(std::lround(1.0 / dt)));
    const Vec3 fall(0, -kGravity, 0);
    const double errorA = (world.body(ia).linearVelocity() - (Vec3(-10, 0, 0) + fall)).norm();
    const double errorB = (world.body(ib).linearVelocity() - (Vec3(5, 0, 0) + fall)).norm();
    EXPECT_LT(errorA, 1e-9) << "dt " << dt;
    EXPECT_LT(errorB, 1e-9) << "dt " << dt;
    worst = std::max({worst, errorA, errorB});
  }
  measured("worst_velocity_error_mps", worst);
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsLinearCastBoxElastic
// at a speed that needs no cast (2 m/s; the 120 m/s version is in
// fast_bodies_test.cpp): equal unit boxes, restitution 1, head on. Jolt:
// velocities reversed within 1e-6, no spin. Ours: 1e-9 m/s, spin below 1e-9
// rad/s (four face points, solved as a block: bounce.h).
TEST(PeerBounce, EqualMassBoxesHeadOnExchangeVelocities) {
  World world(weightless());
  BodyDefinition a = box(Vec3::Constant(0.5), Vec3(-1.5, 0, 0), 1.0, material(1.0, 0.6));
  a.linearVelocity = Vec3(2, 0, 0);
  BodyDefinition b = box(Vec3::Constant(0.5), Vec3(1.5, 0, 0), 1.0, material(1.0, 0.6));
  b.linearVelocity = Vec3(-2, 0, 0);
  const BodyId ia = world.addBody(a), ib = world.addBody(b);
  stepN(world, 90);
  const double error = std::max((world.body(ia).linearVelocity() - Vec3(-2, 0, 0)).norm(),
                                (world.body(ib).linearVelocity() - Vec3(2, 0, 0)).norm());
  const double spin = std::max(world.body(ia).angularVelocity().norm(), world.body(ib).angularVelocity().norm());
  measured("velocity_error_mps", error);
  measured("spin_rad_s", spin);
  EXPECT_LT(error, 1e-9);
  EXPECT_LT(spin, 1e-9);
}

// Jolt PhysicsTests.cpp::TestMinVelocityForRestitution: radius-1 balls 2 m
// apart, one at 1 m/s, restitution 1, no gravity; the threshold (Jolt's
// mMinVelocityForRestitution, physdbg's restitutionThreshold) set to 1.01
// m/s gives a plastic impact (both at 0.5), to 0.99 an elastic one (0 and 1).
// Jolt: 1e-6. Ours: 1e-9 m/s.
TEST(PeerBounce, RestitutionThresholdDecidesBetweenPlasticAndElastic) {
  double worst = 0.0;
  for (const double threshold : {1.01, 0.99}) {
    WorldSettings s = weightless();
    s.solver.restitutionThreshold = threshold;
    World world(s);
    BodyDefinition a = sphere(1.0, Vec3(0, -2, 0), 1.0, material(1.0, 0.6));
    a.linearVelocity = Vec3(0, 1, 0);
    const BodyId ia = world.addBody(a);
    const BodyId ib = world.addBody(sphere(1.0, Vec3(0, 2, 0), 1.0, material(1.0, 0.6)));
    stepN(world, 150);
    const Vec3 expectedA = threshold > 1.0 ? Vec3(0, 0.5, 0) : Vec3::Zero();
    const Vec3 expectedB = threshold > 1.0 ? Vec3(0, 0.5, 0) : Vec3(0, 1, 0);
    const double error = std::max((world.body(ia).linearVelocity() - expectedA).norm(),
                                  (world.body(ib).linearVelocity() - expectedB).norm());
    EXPECT_LT(error, 1e-9) << "threshold " << threshold;
    worst = std::max(worst, error);
  }
  measured("worst_velocity_error_mps", worst);
}

// Box2D test_restitution.c::ThresholdTest: an elastic ball driven at the
// ground (no gravity) at 0.5, 0.9, 1.5 and 4 times the threshold. Box2D:
// below it the ratio out/in is at most 0.05, above it at least 0.9. The
// analytic answers are 0 and 1. Ours: within 1e-9 of them.
TEST(PeerBounce, BelowTheThresholdNothingBouncesAboveItEverythingDoes) {
  double worst = 0.0;
  for (const double scale : {0.5, 0.9, 1.5, 4.0}) {
    World world(weightless());
    world.addBody(floorSlab(0.0, 40.0, material(0.0, 0.0)));
    const double speed = scale * world.settings().solver.restitutionThreshold;
    BodyDefinition ball = sphere(0.5, Vec3(0, 0.5 + 0.5 * speed * world.settings().dt, 0), 1.0, material(1.0, 0.0));
    ball.linearVelocity = Vec3(0, -speed, 0);
    const BodyId id = world.addBody(ball);
    stepN(world, 60);
    const double ratio = world.body(id).linearVelocity().y() / speed;
    const double expected = scale < 1.0 ? 0.0 : 1.0;
    EXPECT_NEAR(ratio, expected, 1e-9) << "scale " << scale;
    worst = std::max(worst, std::abs(ratio - expected));
  }
  measured("worst_ratio_error", worst);
}

// Jolt PhysicsTests.cpp::TestPhysicsCollisionInelastic: a radius-1 ball with
// restitution 0 reaches the floor after 1 s; one step later its velocity is
// zero (Jolt 1e-4) and it lies at the floor (1e-4 m), and stays there for 1 s
// more. Jolt's resting height is its slop; replaced by the soft contact's: a
// load m g on a contact of frequency f settles g / (2 pi f)^2 deep
// (resting_load.h; f = 60 Hz here: 0.069 mm). Ours: velocity within 1e-5
// m/s; after the impact step between touching and that depth (within 1e-6
// m), after 1 s at that depth within 1e-6 m.
TEST(PeerBounce, InelasticBallStopsOnTheFloorInTheImpactStep) {
  World world(settings());
  world.addBody(floorSlab());
  const double h = substep(world.settings());
  const long fallSubsteps = 60L * flightSubsteps(world.settings());
  // Released so that it reaches y = 1 - 1e-4 after 60 steps (Jolt's cFloorHitPos).
  const double hit = 1.0 - 1e-4;
  const double start = hit - eulerPosition(0.0, 0.0, -kGravity, h, fallSubsteps);
  const BodyId id = world.addBody(sphere(1.0, Vec3(0, start, 0), 1.0, material(0.0, 0.6)));
  stepN(world, 61);
  const double omega = 2.0 * std::numbers::pi * world.settings().solver.contactHertz;
  const double depth = kGravity / (omega * omega);
  measured("speed_after_impact_step_mps", world.body(id).linearVelocity().norm());
  measured("height_after_impact_step_m", world.body(id).position().y());
  EXPECT_LT(world.body(id).linearVelocity().norm(), 1e-5);
  // Stopped on the surface, the soft contact sinking it towards its depth.
  EXPECT_LE(world.body(id).position().y(), 1.0 + 1e-6);
  EXPECT_GE(world.body(id).position().y(), 1.0 - depth - 1e-6);
  stepN(world, 60);
  measured("height_after_1s_m", world.body(id).position().y());
  EXPECT_LT(world.body(id).linearVelocity().norm(), 1e-5);
  EXPECT_NEAR(world.body(id).position().y(), 1.0 - depth, 1e-6);
}

// Box2D test_restitution.c::TwoPointTest: a flat box (1 x 0.25 half extents)
// lands on both edges at once at 5 m/s (no gravity, frictionless), e = 0.5
// and 0.9. Box2D: out/in within 0.01 of e, spin below 0.03 rad/s. The
// rigid-body answer is e and no spin at all. Ours: e within 1e-9 and spin
// below 1e-9 rad/s (the bound for a flat landing).
TEST(PeerBounce, FlatBoxLandingOnTwoEdgesLeavesWithoutSpin) {
  const double speed = 5.0, dt = 1.0 / 60.0;
  double worstRatio = 0.0, worstSpin = 0.0;
  for (const double e : {0.5, 0.9}) {
    World world(weightless(dt));
    world.addBody(floorSlab(0.0, 40.0, material(0.0, 0.0)));
    BodyDefinition plank = box(Vec3(1.0, 0.25, 0.5), Vec3(0, 0.25 + 0.5 * speed * dt, 0), 1.0, material(e, 0.0));
    plank.linearVelocity = Vec3(0, -speed, 0);
    const BodyId id = world.addBody(plank);
    stepN(world, 60);
    const double ratio = world.body(id).linearVelocity().y() / speed;
    const double spin = world.body(id).angularVelocity().norm();
    EXPECT_NEAR(ratio, e, 1e-9) << "e " << e;
    EXPECT_LT(spin, 1e-9) << "e " << e;
    worstRatio = std::max(worstRatio, std::abs(ratio - e));
    worstSpin = std::max(worstSpin, spin);
  }
  measured("worst_ratio_error", worstRatio);
  measured("worst_spin_rad_s", worstSpin);
}

// Box2D test_restitution.c::SingleBoxTest: a unit box, restitution 1,
// frictionless, dropped flat from 10 m (gravity 10). Box2D: first-bounce
// spin below 0.01 rad/s, four apexes within [0.95, 1.001] of the drop. The
// rigid-body answer is no spin and the drop height every time. Ours: spin
// below 1e-9 rad/s after each bounce and E/g within 1e-6 m of the release
// height (a 1e-7 share).
TEST(PeerBounce, FlatBoxDroppedWithRestitutionOneBouncesStraightBackUp) {
  WorldSettings s = settings();
  s.gravity = Vec3(0, -10, 0);
  World world(s);
  world.addBody(floorSlab(0.0, 20.0, material(0.0, 0.0)));
  const double release = 10.0;
  const BodyId id = world.addBody(box(Vec3::Constant(0.5), Vec3(0, release, 0), 1.0, material(1.0, 0.0)));
  const double h = substep(world.settings());
  double worstSpin = 0.0, worstHeight = 0.0;
  for (int bounce = 0; bounce < 4; ++bounce) {
    SCOPED_TRACE(bounce);
    ASSERT_TRUE(stepUntilRisingClear(world, id, 1200));
    const RigidBody& body = world.body(id);
    const double apex = flightEnergy(body.position().y(), body.linearVelocity().y(), 10.0, h) / 10.0;
    worstSpin = std::max(worstSpin, body.angularVelocity().norm());
    worstHeight = std::max(worstHeight, std::abs(apex - release));
    EXPECT_LT(body.angularVelocity().norm(), 1e-9);
    EXPECT_NEAR(apex, release, 1e-6);
    stepThroughApex(world, id, 600);
  }
  measured("worst_spin_rad_s", worstSpin);
  measured("worst_apex_error_m", worstHeight);
}

// Box2D test_restitution.c::SpinTest: the flat box carrying spin about the
// axis along its edges (0, 0.5, 1 and 2 rad/s), restitution 1, frictionless,
// no gravity, landing at 5 m/s. Both edges stay in contact and the normal
// constraints are linear in the velocities, so e = 1 reverses both the
// normal speed and the spin. Box2D: within 0.05. Ours: within 0.005 (ten
// times tighter; the spin turns the box by up to 0.03 rad within the step,
// which moves the contact points by that share of their lever arm).
TEST(PeerBounce, SpinningFlatBoxReversesItsSpeedAndItsSpin) {
  const double speed = 5.0, dt = 1.0 / 60.0;
  double worst = 0.0;
  for (const double spin : {0.0, 0.5, 1.0, 2.0}) {
    World world(weightless(dt));
    world.addBody(floorSlab(0.0, 40.0, material(0.0, 0.0)));
    BodyDefinition plank = box(Vec3(1.0, 0.25, 0.5), Vec3(0, 0.25 + 0.5 * speed * dt, 0), 1.0, material(1.0, 0.0));
    plank.linearVelocity = Vec3(0, -speed, 0);
    plank.angularVelocity = Vec3(0, 0, spin);
    const BodyId id = world.addBody(plank);
    stepN(world, 60);
    const double speedError = std::abs(world.body(id).linearVelocity().y() - speed);
    const double spinError = std::abs(world.body(id).angularVelocity().z() + spin);
    EXPECT_LT(speedError, 0.005) << "spin " << spin;
    EXPECT_LT(spinError, 0.005) << "spin " << spin;
    worst = std::max({worst, speedError, spinError});
  }
  measured("worst_error", worst);
}

// Box2D test_restitution.c::CornerTest (the wide case): a unit box tilted
// -0.4 rad dropped from 5 m (gravity 10), restitution 1, frictionless, lands
// on one edge. Box2D: spin within 2% of the single-point law (J = 2 u / k, k =
// 1/m + rn^2 / I, spin = rn J / I with u the impact speed) and the energy after
// the rebound within [0.97, 1.01] of the start. The box is held in its plane
// (Box2D is 2D): translation along z and rotation about x and y locked.
// Ours: spin within 0.5%, energy within [0.997, 1.001]. The impact speed is
// the one the flight energy gives at the floor (u^2/2 + g h u / 2 = E).
// Not ten times Box2D's 2%: restitution is solved once, at the end of the
// step, for the point's end-of-step speed, and gravity's pull after the
// impact acts on the centre alone while the impulse also turns the box, so
// the end-of-step target overstates the spin by about g t_rest rn / (k I)
// (measured 0.23%).
// Failed while a corner's gap, lifted 0.17 mm by the turn that follows the
// impact, counted as not reached: the impact was plastic (10.43 rad/s, the
// e = 0 answer) and the box never rose clear again.
TEST(PeerBounce, CornerLandingSpinFollowsTheSinglePointLaw) {
  const double g = 10.0, angle = -0.4;
  WorldSettings s = settings();
  s.gravity = Vec3(0, -g, 0);
  World world(s);
  world.addBody(floorSlab(0.0, 20.0, material(0.0, 0.0)));
  BodyDefinition def = box(Vec3::Constant(0.5), Vec3(0, 5, 0), 1.0, material(1.0, 0.0));
  def.orientation = Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
  def.lockTranslation = {false, false, true};
  def.lockRotation = {true, true, false};
  const BodyId id = world.addBody(def);
  const double inertia = world.body(id).localInertia()(2, 2);  // 1/6
  const double h = substep(world.settings());
  const Vec3 corner = def.orientation * Vec3(0.5, -0.5, 0.0);
  const double cornerHeight = 5.0 + corner.y();
  const auto energy = [&](const RigidBody& body) {
    const double v = body.linearVelocity().y();
    return 0.5 * body.linearVelocity().squaredNorm() + 0.5 * inertia * body.angularVelocity().squaredNorm() +
           g * body.position().y() - 0.5 * g * h * v;
  };
  const double startEnergy = energy(world.body(id));
  // Impact speed from the flight energy of the corner's fall.
  const double flight = g * cornerHeight;
  const double half = 0.5 * g * h;
  const double impact = -half + std::sqrt(half * half + 2.0 * flight);
  const double rn = corner.x();
  const double k = 1.0 + rn * rn / inertia;
  const double expectedSpin = rn * (2.0 * impact / k) / inertia;
  double spin = 0.0;
  for (int i = 0; i < 400 && spin == 0.0; ++i) {
    world.step();
    spin = world.body(id).angularVelocity().z();
  }
  measured("spin_rad_s", spin);
  measured("expected_spin_rad_s", expectedSpin);
  EXPECT_NEAR(spin, expectedSpin, 0.005 * std::abs(expectedSpin));
  // Leave the floor, then read the energy once clear and falling.
  double ratio = 0.0;
  for (int i = 0; i < 400; ++i) {
    world.step();
    const RigidBody& body = world.body(id);
    if (body.linearVelocity().y() < 0.0 && body.position().y() > 1.0) {
      ratio = energy(body) / startEnergy;
      break;
    }
  }
  measured("energy_ratio", ratio);
  EXPECT_GE(ratio, 0.997);
  EXPECT_LE(ratio, 1.001);
}

// Box2D test_restitution.c::EnergyTest: restitution 1 with friction 0.6,
// dropped every way that used to gain energy (a spinning corner, a tumble, a
// flat landing with spin, a corner, a box onto a resting box). Box2D: the
// peak energy over the run at most 1.001 of the start with continuous
// collision, 1.02 without. physdbg's speculative contacts land bodies on the
// surface as Box2D's continuous path does. Ours: at most 1.0001. Planar as
// in Box2D (locks), energy with the half-substep phase term.
TEST(PeerBounce, ElasticBodiesNeverGainEnergy) {
  struct Drop {
    const char* name;
    double angle, spin, height, velocityY;
    bool stack;
    int steps;
  };
  const Drop drops[] = {
      {"spinning corner", -1.43, 7.9, 0.7, -1.9, false, 300},
      {"tumble", -0.3, 3.0, 8.0, 0.0, false, 600},
      {"flat with spin", 0.0, 2.0, 2.0, -5.0, false, 300},
      {"corner", -0.2, 0.0, 5.0, 0.0, false, 600},
      {"two box", 0.0, 0.0, 4.0, 0.0, true, 900},
  };
  const double g = 10.0;
  double worst = 0.0;
  for (const Drop& drop : drops) {
    WorldSettings s = settings();
    s.gravity = Vec3(0, -g, 0);
    World world(s);
    world.addBody(floorSlab(0.0, 40.0, material(0.0, 0.6)));
    const auto planar = [](BodyDefinition def) {
      def.lockTranslation = {false, false, true};
      def.lockRotation = {true, true, false};
      return def;
    };
    std::vector<BodyId> ids;
    if (drop.stack)
      ids.push_back(world.addBody(planar(box(Vec3::Constant(0.5), Vec3(0, 0.5, 0), 1.0, material(1.0, 0.6)))));
    BodyDefinition def = planar(box(Vec3::Constant(0.5), Vec3(0, drop.height, 0), 1.0, material(1.0, 0.6)));
    def.orientation = Quat(Eigen::AngleAxisd(drop.angle, Vec3::UnitZ()));
    def.angularVelocity = Vec3(0, 0, drop.spin);
    def.linearVelocity = Vec3(0, drop.velocityY, 0);
    ids.push_back(world.addBody(def));
    const double h = substep(world.settings());
    const auto energy = [&] {
      double total = 0.0;
      for (BodyId id : ids) {
        const RigidBody& body = world.body(id);
        total += body.kineticEnergy() + g * body.position().y() - 0.5 * g * h * body.linearVelocity().y();
      }
      return total;
    };
    const double start = energy();
    double peak = start;
    for (int i = 0; i < drop.steps; ++i) {
      world.step();
      peak = std::max(peak, energy());
    }
    EXPECT_LE(peak / start, 1.0001) << drop.name;
    worst = std::max(worst, peak / start);
  }
  measured("worst_peak_energy_ratio", worst);
}

// Box2D test_restitution.c::RestingTest: ten unit boxes stacked on a ground
// of restitution 0.9, themselves 0.9, friction 0.6, gravity 10; after 2 s of
// settling, 5 s more. Box2D: the top box drifts less than 0.01 m and no box
// is faster than 0.05 m/s. Ours: 0.001 m and 0.005 m/s.
TEST(PeerBounce, RestitutionDoesNotWakeASettledStack) {
  WorldSettings s = settings();
  s.gravity = Vec3(0, -10, 0);
  World world(s);
  world.addBody(floorSlab(0.0, 40.0, material(0.9, 0.6)));
  std::vector<BodyId> boxes;
  for (int i = 0; i < 10; ++i)
    boxes.push_back(world.addBody(box(Vec3::Constant(0.5), Vec3(0, 0.5 + i, 0), 1.0, material(0.9, 0.6))));
  stepN(world, 120);
  const double settled = world.body(boxes.back()).position().y();
  double drift = 0.0, peak = 0.0;
  for (int i = 0; i < 300; ++i) {
    world.step();
    drift = std::max(drift, std::abs(world.body(boxes.back()).position().y() - settled));
    for (BodyId id : boxes) peak = std::max(peak, world.body(id).linearVelocity().norm());
  }
  measured("top_drift_m", drift);
  measured("peak_speed_mps", peak);
  EXPECT_LT(drift, 0.001);
  EXPECT_LT(peak, 0.005);
}

// Newton's cradle (the case; the row is Jolt
// PhysicsTests.cpp::TestPhysicsActivateDuringStep's row of touching bodies,
// here elastic balls): five balls of restitution 1 in a row, a sixth arrives
// at 2 m/s. The analytic answer (impacts passed down the row one by one) is
// the far ball leaving at 2 m/s and every other at rest, momentum and energy
// kept, and each ball between one gap on from where it started (it crossed
// its gap to strike the next). No peer tolerance (the
// issue asks 1% of momentum and energy). Ours: for gaps between the balls of
// 0, 1 mm and a step's travel (2 m/s x 1/60 s), so the impacts fall in one
// step or in several: momentum within 1e-9, energy within 1e-6 relative,
// every ball within 1e-6 m/s, the middle four within 1e-6 m of one gap on
// (a gap inside the 5 mm slop counts as touching, so there within the gap).
// Failed while restitution bounced each manifold on its own: the striker
// came back at -0.25, the first ball at -0.266 and the other four left
// together at 0.63 m/s (touching row; 29% of the energy lost with 1 mm gaps).
TEST(PeerBounce, NewtonsCradlePassesTheImpactToTheFarBall) {
  for (const double gap : {0.0, 1e-3, 2.0 / 60.0}) {
    SCOPED_TRACE(gap);
    const double tolerance = 1e-6;
    World world(weightless());
    std::vector<BodyId> balls;
    BodyDefinition striker = sphere(0.5, Vec3(-2.0, 0, 0), 1.0, material(1.0, 0.0));
    striker.linearVelocity = Vec3(2, 0, 0);
    balls.push_back(world.addBody(striker));
    for (int i = 0; i < 5; ++i)
      balls.push_back(world.addBody(sphere(0.5, Vec3(i * (1.0 + gap), 0, 0), 1.0, material(1.0, 0.0))));
    stepN(world, 90);
    double worst = 0.0, energy = 0.0, momentum = 0.0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const Vec3 velocity = world.body(balls[i]).linearVelocity();
      const Vec3 expected = i + 1 == balls.size() ? Vec3(2, 0, 0) : Vec3::Zero();
      EXPECT_LT((velocity - expected).norm(), tolerance) << "ball " << i << " velocity " << velocity.transpose();
      worst = std::max(worst, (velocity - expected).norm());
      energy += world.body(balls[i]).kineticEnergy();
      momentum += velocity.x();
    }
    EXPECT_NEAR(momentum, 2.0, 1e-9);
    EXPECT_NEAR(energy, 2.0, 1e-6);
    for (int i = 1; i < 5; ++i)
      EXPECT_NEAR(world.body(balls[i]).position().x(), (i - 1) * (1.0 + gap) + gap, gap < 5e-3 ? gap + 1e-6 : 1e-6)
          << "ball " << i;
    measured("worst_velocity_error_mps", worst);
  }
}

}  // namespace
}  // namespace physdbg::peers
