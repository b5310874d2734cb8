// Sleeping and waking: a body that starts asleep (the scene key "asleep",
// loaded with the scenes library), is woken, settles and sleeps again; an
// impulse waking a sleeper; a sliding and a rolling ball passing their
// momentum to a sleeping ball. Cases from Jolt's UnitTests/Physics/
// PhysicsTests.cpp (TestPhysicsActivationDeactivation),
// ContactListenerTests.cpp (TestWereBodiesInContact's AddImpulse) and
// MotionQualityLinearCastTests.cpp (TestLinearCastBoxVsInactiveDiscreteBox),
// and the issue's ball rolling into a sleeping ball.
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// Jolt PhysicsTests.cpp::TestPhysicsActivationDeactivation at 1, 2 and 4
// steps per 1/60 s: a box of half extent 0.5 created inactive at y = 5 over a
// floor. Jolt: unmoved (==) and inactive for 1 s; activated, it has no
// velocity, gains some in one step; 5 s later it rests at y = 0.5 within 1.1
// slops (0.022 m) with no velocity (1e-6) and has been deactivated exactly
// once. Ours: the same with the body asleep from the scene file; the first
// step's velocity exactly -g dt (1e-12); at rest within 2.2e-3 m (ten times
// tighter) and velocities exactly 0 (a sleeping body's are zeroed); one
// fall into sleep.
TEST(PeerSleep, BodyCreatedAsleepStaysPutUntilWokenThenSettlesAndSleeps) {
  double worstHeight = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    SCOPED_TRACE(dt);
    char json[1024];
    std::snprintf(json, sizeof json, R"({"dt": %.17g, "bodies": [
        {"shape": {"box": {"half_extents": [100, 1, 100]}}, "position": [0, -1, 0], "static": true},
        {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 5, 0], "asleep": true}]})",
                  dt);
    World world = sceneWorld(json, "asleep.json");
    const BodyId id = 1;
    ASSERT_TRUE(world.isAsleep(id));
    const int second = static_cast<int>(std::lround(1.0 / dt));
    stepN(world, second);
    EXPECT_EQ(world.body(id).position(), Vec3(0, 5, 0));
    EXPECT_TRUE(world.isAsleep(id));
    world.wake(id);
    EXPECT_FALSE(world.isAsleep(id));
    EXPECT_EQ(world.body(id).linearVelocity(), Vec3::Zero());
    world.step();
    EXPECT_FALSE(world.isAsleep(id));
    EXPECT_NEAR(world.body(id).linearVelocity().y(), -kGravity * dt, 1e-12);
    int fellAsleep = 0;
    bool asleep = false;
    for (int i = 0; i < 5 * second; ++i) {
      world.step();
      if (world.isAsleep(id) && !asleep) ++fellAsleep;
      asleep = world.isAsleep(id);
    }
    EXPECT_TRUE(world.isAsleep(id));
    EXPECT_EQ(fellAsleep, 1);
    EXPECT_LT((world.body(id).position() - Vec3(0, 0.5, 0)).norm(), 2.2e-3);
    EXPECT_EQ(world.body(id).linearVelocity(), Vec3::Zero());
    EXPECT_EQ(world.body(id).angularVelocity(), Vec3::Zero());
    worstHeight = std::max(worstHeight, (world.body(id).position() - Vec3(0, 0.5, 0)).norm());
  }
  measured("worst_rest_offset_m", worstHeight);
}

// Jolt ContactListenerTests.cpp::TestWereBodiesInContact lifts a resting
// body off the floor with AddImpulse, which activates it. Here a box that
// has fallen asleep on the floor is given an upward impulse of 5 N s (1 kg)
// through a scheduled force: it wakes in that step and leaves with 5 m/s
// less the step's gravity, the floor taking no part (it only pushes). No
// peer tolerance on the speed (Jolt counts contacts). Ours: 5 - g dt within
// 1e-9 m/s.
TEST(PeerSleep, ImpulseWakesASleepingBodyAndActsInFull) {
  World world(settings(1.0 / 60.0, true));
  world.addBody(floorSlab());
  const BodyId id = world.addBody(box(Vec3::Constant(0.5), Vec3(0, 0.5, 0)));
  for (int i = 0; i < 300 && !world.isAsleep(id); ++i) world.step();
  ASSERT_TRUE(world.isAsleep(id));
  world.scheduleForce(
      {id, Vec3(0, 5, 0), false, ForceMode::Impulse, std::nullopt, world.stepCount(), world.stepCount() + 1});
  world.step();
  EXPECT_FALSE(world.isAsleep(id));
  const double expected = 5.0 - kGravity * world.settings().dt;
  measured("vertical_speed_mps", world.body(id).linearVelocity().y());
  EXPECT_NEAR(world.body(id).linearVelocity().y(), expected, 1e-9);
}

// Two balls on a floor, the second asleep. Returns the world and ids after
// the first has been set moving at `speed` (with `spin`) towards the second.
struct TwoBalls {
  World world;
  BodyId floor = 0, mover = 0, sleeper = 0;
};

// The balls themselves are frictionless: with the Maximum rule the floor's
// friction is the ball-floor pairs' and the ball-ball pair has none.
TwoBalls twoBalls(double floorFriction, double speed, double spin) {
  WorldSettings s = settings(1.0 / 60.0, true);
  s.solver.combine.friction = CombineRule::Maximum;
  TwoBalls scene{World(s), 0, 0, 0};
  scene.floor = scene.world.addBody(floorSlab(0.0, 100.0, material(0.0, floorFriction)));
  scene.mover = scene.world.addBody(sphere(0.5, Vec3(-3, 0.5, 0), 1.0, material(1.0, 0.0)));
  scene.sleeper = scene.world.addBody(sphere(0.5, Vec3(0, 0.5, 0), 1.0, material(1.0, 0.0)));
  // Both settle into the floor and fall asleep; then the first is sent off.
  for (int i = 0; i < 300 && !(scene.world.isAsleep(scene.mover) && scene.world.isAsleep(scene.sleeper)); ++i)
    scene.world.step();
  scene.world.body(scene.mover).setLinearVelocity(Vec3(speed, 0, 0));
  scene.world.body(scene.mover).setAngularVelocity(Vec3(0, 0, spin));
  return scene;
}

// The issue's case, in the form of Jolt
// MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsInactiveDiscreteBox (a
// moving body hitting an inactive one shares its momentum; Jolt 1e-6): a
// ball slides (frictionless floor) at 2 m/s into an equal sleeping ball,
// restitution 1. The analytic answer: the mover stops, the sleeper leaves at
// 2 m/s, momentum kept. Ours: both velocities within 1e-6 m/s (1e-9 of the
// momentum is the tilt the two balls' resting depths could give the normal,
// far below), momentum along x to 1e-12 relative, the sleeper awake.
TEST(PeerSleep, SlidingBallPassesItsMomentumToASleepingBall) {
  TwoBalls scene = twoBalls(0.0, 2.0, 0.0);
  ASSERT_TRUE(scene.world.isAsleep(scene.sleeper));
  stepN(scene.world, 120);
  const RigidBody &mover = scene.world.body(scene.mover), &sleeper = scene.world.body(scene.sleeper);
  EXPECT_FALSE(scene.world.isAsleep(scene.sleeper));
  const double error = std::max(std::abs(mover.linearVelocity().x()), std::abs(sleeper.linearVelocity().x() - 2.0));
  measured("velocity_error_mps", error);
  EXPECT_LT(error, 1e-6);
  EXPECT_NEAR(mover.linearVelocity().x() + sleeper.linearVelocity().x(), 2.0, 1e-12 * 2.0);
}

// The same with floor friction 0.5 (the balls frictionless against each
// other) and the mover rolling (w = -v / r) at 2 m/s.
// Floor forces act at floor level, so about any point of the floor they
// have no moment (the normal force balances the weight): the two balls'
// angular momentum about the floor, sum of I w - m y v_x, is kept through
// the impact (internal) and the sliding that follows. The mover is left
// spinning without speed and rolls on at 2/7 v0, the sleeper slides off at
// v0 without spin and rolls on at 5/7 v0. No peer tolerance. Ours: the
// angular momentum within 1e-6 relative at every step, the final speeds
// within 1e-4 m/s of 2/7 and 5/7 v0.
// Fails today: the sleeper now takes the impact in the step and it is
// elastic, but the bounce is sized at the end of the step, after floor
// friction has already acted on both balls for the rest of it, so it is
// 4% too strong: they roll on at 0.513 and 1.487 m/s instead of 0.571 and
// 1.429; the angular momentum drifts by 3.7e-5. (Before the sleeper woke
// within the step the impact was plastic: 0.99966 and 1.00030 m/s.)
TEST(PeerSleep, DISABLED_RollingBallPassesItsMomentumToASleepingBall) {
  const double v0 = 2.0, radius = 0.5;
  TwoBalls scene = twoBalls(0.5, v0, -v0 / radius);
  const auto angularMomentum = [&] {
    double total = 0.0;
    for (const BodyId id : {scene.mover, scene.sleeper}) {
      const RigidBody& body = scene.world.body(id);
      total += body.angularMomentum().z() + body.mass() * (body.position().x() * body.linearVelocity().y() -
                                                           body.position().y() * body.linearVelocity().x());
    }
    return total;
  };
  const double start = angularMomentum();
  double worst = 0.0;
  for (int i = 0; i < 180; ++i) {
    scene.world.step();
    worst = std::max(worst, std::abs(angularMomentum() - start) / std::abs(start));
  }
  measured("worst_angular_momentum_drift", worst);
  measured("mover_speed_mps", scene.world.body(scene.mover).linearVelocity().x());
  measured("sleeper_speed_mps", scene.world.body(scene.sleeper).linearVelocity().x());
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(scene.world.body(scene.mover).linearVelocity().x(), 2.0 / 7.0 * v0, 1e-4);
  EXPECT_NEAR(scene.world.body(scene.sleeper).linearVelocity().x(), 5.0 / 7.0 * v0, 1e-4);
}

}  // namespace
}  // namespace physdbg::peers
