// Speculative contacts: bodies a step or less from the floor, moving at it,
// away from it, or too slowly to reach it. Cases from Jolt's
// UnitTests/Physics/PhysicsTests.cpp (TestPhysics*SpeculativeContactDistance*).
// Jolt's speculative distance is 0.02 m; physdbg finds a pair from 4 slops
// (0.02 m) plus what the pair closes in the step (contactReach), so both of
// Jolt's cases, just inside and just outside 0.02 m, get a contact here.
// Where Jolt reports a contact that never touched, or lets a discrete body
// sink a metre into the floor, the engine-neutral answer replaces it: an
// event only where the bodies meet, and no body passing into the floor.
#include <algorithm>
#include <cmath>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

constexpr double kJoltSpeculativeDistance = 0.02;  // m, PhysicsSettings::mSpeculativeContactDistance

struct BoxAndBall {
  World world;
  BodyId floor = 0, box = 0, ball = 0;
};

// Jolt's setup: no gravity, a floor with its top at y = 0, a box of half
// extent 1 and a ball of radius 1 (5 m apart) with their bottoms `gap` above
// it, both moving at `velocity` along y.
BoxAndBall boxAndBall(double gap, double velocity, double restitution, double floorRestitution = 0.0) {
  BoxAndBall scene{World(weightless()), 0, 0, 0};
  scene.floor = scene.world.addBody(floorSlab(0.0, 100.0, material(floorRestitution, 0.6)));
  BodyDefinition b = box(Vec3::Ones(), Vec3(0, 1.0 + gap, 0), 1.0, material(restitution, 0.6));
  b.linearVelocity = Vec3(0, velocity, 0);
  scene.box = scene.world.addBody(b);
  BodyDefinition s = sphere(1.0, Vec3(5, 1.0 + gap, 0), 1.0, material(restitution, 0.6));
  s.linearVelocity = Vec3(0, velocity, 0);
  scene.ball = scene.world.addBody(s);
  return scene;
}

// A body arriving at 60 m/s (1 m a step) from `gap` above the floor stops
// on it in that step. Returns the worst distance from resting on the
// surface (centre at y = 1) and the worst speed left, over box and ball,
// after the step and after one more.
void expectStoppedOnTheFloor(double gap, double& worstHeight, double& worstSpeed, double& worstSpin) {
  BoxAndBall scene = boxAndBall(gap, -60.0, 0.0);
  RecordingListener events(scene.world);
  for (int step = 1; step <= 2; ++step) {
    scene.world.step();
    for (const BodyId id : {scene.box, scene.ball}) {
      const RigidBody& body = scene.world.body(id);
      SCOPED_TRACE(id == scene.box ? "box" : "ball");
      EXPECT_NEAR(body.position().y(), 1.0, 1e-6) << "step " << step;
      EXPECT_LT(body.linearVelocity().norm(), 1e-6) << "step " << step;
      EXPECT_LT(body.angularVelocity().norm(), 1e-9) << "step " << step;
      worstHeight = std::max(worstHeight, std::abs(body.position().y() - 1.0));
      worstSpeed = std::max(worstSpeed, body.linearVelocity().norm());
      worstSpin = std::max(worstSpin, body.angularVelocity().norm());
    }
    // Begin on the impact step, stay on the next, for each pair.
    const RecordedEvent::Kind kind = step == 1 ? RecordedEvent::Begin : RecordedEvent::Stay;
    EXPECT_EQ(events.count(kind, scene.floor, scene.box), 1) << "step " << step;
    EXPECT_EQ(events.count(kind, scene.floor, scene.ball), 1) << "step " << step;
    EXPECT_EQ(events.events.size(), 2u) << "step " << step;
    events.clear();
  }
}

// Jolt PhysicsTests.cpp::TestPhysicsInsideSpeculativeContactDistanceNoRestitution:
// box and ball 0.9 x 0.02 m above the floor at 1 m a step, restitution 0.
// Jolt: after one step the ball rests at y = 1 (1e-6; the box within 1e-3)
// with velocity -gap/dt (1e-4; box 0.05) — the speed that just closes the
// gap, its own speculative-contact artefact — then at rest one step later;
// Add then Persist events. The engine-neutral answer: a plastic impact
// inside the step leaves both bodies on the surface at rest. Ours: centre at
// y = 1 within 1e-6 m, speed below 1e-6 m/s, spin below 1e-9 rad/s, for box
// and ball alike, after the step and the next; begin, then stay.
TEST(PeerSpeculative, InsideTheDistanceAFastBodyStopsOnTheSurface) {
  double height = 0.0, speed = 0.0, spin = 0.0;
  expectStoppedOnTheFloor(0.9 * kJoltSpeculativeDistance, height, speed, spin);
  measured("worst_height_error_m", height);
  measured("worst_speed_mps", speed);
  measured("worst_spin_rad_s", spin);
}

// Jolt PhysicsTests.cpp::TestPhysicsOutsideOfSpeculativeContactDistance: the
// same bodies 1.1 x 0.02 m above the floor. Jolt: no contact in the first
// step, both bodies sink to 1 m minus the gap into the floor (discrete
// bodies), contacts in the second. Replaced by the engine-neutral answer: a
// body that reaches the floor within the step stops on it. Ours: as inside
// the distance.
TEST(PeerSpeculative, OutsideTheDistanceAFastBodyStillStopsOnTheSurface) {
  double height = 0.0, speed = 0.0, spin = 0.0;
  expectStoppedOnTheFloor(1.1 * kJoltSpeculativeDistance, height, speed, spin);
  measured("worst_height_error_m", height);
  measured("worst_speed_mps", speed);
  measured("worst_spin_rad_s", spin);
}

// Jolt PhysicsTests.cpp::TestPhysicsInsideSpeculativeContactDistanceWithRestitution:
// as above with restitution 1. Jolt: after one step each body is 1 m above
// where it started ("travelling the extra distance to the floor and back for
// free", box 0.01 m, ball 1e-5 m) moving up at 60 m/s (box 0.1, ball 2e-4);
// the next step removes both contacts. The engine-neutral answer: the body
// leaves at 60 m/s exactly, from somewhere between the surface (y = 1: the
// bounce applied at the end of the step, as physdbg and Box2D do) and where
// an exact impact puts it (y = 2 - gap); never higher. Ours: velocity within
// 1e-9 of 60 m/s (1e-11 relative), no spin (1e-9 rad/s), height in [1, 2 -
// gap] within 1e-9 m. Events: begin in step 1; a body left on the surface
// starts step 2 touching, so a stay there (as Jolt's
// MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsLinearCastBoxElastic
// expects a Persist "since they were initially overlapping"), the end in
// step 3; a body that took the exact path ends in step 2.
TEST(PeerSpeculative, ElasticBodiesLeaveAtTheSpeedTheyArrivedWith) {
  const double gap = 0.9 * kJoltSpeculativeDistance;
  BoxAndBall scene = boxAndBall(gap, -60.0, 1.0);
  RecordingListener events(scene.world);
  scene.world.step();
  double worstSpeed = 0.0;
  for (const BodyId id : {scene.box, scene.ball}) {
    SCOPED_TRACE(id == scene.box ? "box" : "ball");
    const RigidBody& body = scene.world.body(id);
    EXPECT_NEAR(body.linearVelocity().y(), 60.0, 1e-9);
    EXPECT_LT(body.angularVelocity().norm(), 1e-9);
    EXPECT_GE(body.position().y(), 1.0 - 1e-9);
    EXPECT_LE(body.position().y(), 2.0 - gap + 1e-9);
    worstSpeed = std::max(worstSpeed, std::abs(body.linearVelocity().y() - 60.0));
    measured(id == scene.box ? "box_height_m" : "ball_height_m", body.position().y());
  }
  measured("worst_speed_error_mps", worstSpeed);
  EXPECT_EQ(events.count(RecordedEvent::Begin, scene.floor, scene.box), 1);
  EXPECT_EQ(events.count(RecordedEvent::Begin, scene.floor, scene.ball), 1);
  EXPECT_EQ(events.events.size(), 2u);
  events.clear();
  const double heights[] = {scene.world.body(scene.box).position().y(), scene.world.body(scene.ball).position().y()};
  scene.world.step();
  scene.world.step();
  const BodyId ids[] = {scene.box, scene.ball};
  for (int i = 0; i < 2; ++i) {
    SCOPED_TRACE(i == 0 ? "box" : "ball");
    const bool onSurface = heights[i] < 1.0 + 1e-9;
    EXPECT_EQ(events.count(RecordedEvent::Stay, scene.floor, ids[i]), onSurface ? 1 : 0);
    EXPECT_EQ(events.count(RecordedEvent::End, scene.floor, ids[i]), 1);
    for (const RecordedEvent& event : events.events)
      if (event.b == ids[i] && event.kind == RecordedEvent::End) {
        EXPECT_EQ(event.step, onSurface ? 3 : 2);
      }
  }
  EXPECT_EQ(events.count(RecordedEvent::Begin), 0);
}

// Jolt PhysicsTests.cpp::TestPhysicsInsideSpeculativeContactDistanceNoHit:
// an elastic ball 0.9 x 0.02 m above an elastic floor, no restitution
// threshold, moving down at 0.9 of the gap per step: it does not reach the
// floor in the first step, so its velocity must be exactly unchanged (Jolt:
// ==), and it bounces in the second (Jolt: velocity reversed, 1e-6). Jolt
// reports the speculative contact as added in the first step; the
// engine-neutral answer is no event before the bodies meet (the issue: no
// bounce from a speculative contact not reached in the step, `begin` in the
// step the impact changed velocities). Ours: step 1 velocity bit-exact and
// position y0 + v dt within 1e-12 m, no event; step 2 velocity reversed
// within 1e-12 m/s, one begin.
// Failed while the step's last relax sweep pushed on unreached points: the
// ball was slowed in step 1 from 0.972 to 0.864 m/s (1 event in step 1),
// and left the floor in step 2 at 0.864 m/s instead of 0.972.
TEST(PeerSpeculative, ASpeculativeContactNotReachedInTheStepDoesNothing) {
  const double gap = 0.9 * kJoltSpeculativeDistance;
  WorldSettings s = weightless();
  s.solver.restitutionThreshold = 0.0;
  World world(s);
  const BodyId floor = world.addBody(floorSlab(0.0, 100.0, material(1.0, 0.6)));
  const double speed = 0.9 * gap / s.dt;
  BodyDefinition def = sphere(1.0, Vec3(0, 1.0 + gap, 0), 1.0, material(1.0, 0.6));
  def.linearVelocity = Vec3(0, -speed, 0);
  const BodyId ball = world.addBody(def);
  RecordingListener events(world);
  world.step();
  EXPECT_EQ(world.body(ball).linearVelocity(), Vec3(0, -speed, 0));
  EXPECT_NEAR(world.body(ball).position().y(), 1.0 + gap - speed * s.dt, 1e-12);
  EXPECT_TRUE(events.events.empty()) << "an event before the ball reached the floor";
  measured("events_in_step_1", static_cast<double>(events.events.size()));
  events.clear();
  world.step();
  measured("velocity_after_step_2_mps", world.body(ball).linearVelocity().y());
  EXPECT_NEAR(world.body(ball).linearVelocity().y(), speed, 1e-12);
  EXPECT_EQ(events.count(RecordedEvent::Begin, floor, ball), 1);
}

// Jolt PhysicsTests.cpp::TestPhysicsInsideSpeculativeContactDistanceMovingAway:
// box and ball 0.9 x 0.02 m above the floor moving up at 60 m/s,
// restitution 1. Jolt: they move unimpeded (position, velocity, spin within
// 1e-6) but an Add is reported ("wrong ... the downside of speculative
// contacts") and a Remove next step. Engine-neutral: nothing touched, so no
// event at all. Ours: position y0 + v dt within 1e-12 m, velocity and spin
// bit-exact, no event in either step.
TEST(PeerSpeculative, BodiesMovingAwayAreNotTouched) {
  const double gap = 0.9 * kJoltSpeculativeDistance;
  BoxAndBall scene = boxAndBall(gap, 60.0, 1.0);
  RecordingListener events(scene.world);
  scene.world.step();
  double worst = 0.0;
  for (const BodyId id : {scene.box, scene.ball}) {
    const RigidBody& body = scene.world.body(id);
    EXPECT_EQ(body.linearVelocity(), Vec3(0, 60, 0));
    EXPECT_EQ(body.angularVelocity(), Vec3::Zero());
    EXPECT_NEAR(body.position().y(), 1.0 + gap + 60.0 * scene.world.settings().dt, 1e-12);
    worst = std::max(worst, std::abs(body.position().y() - (1.0 + gap + 60.0 * scene.world.settings().dt)));
  }
  scene.world.step();
  measured("worst_position_error_m", worst);
  measured("events", static_cast<double>(events.events.size()));
  EXPECT_TRUE(events.events.empty());
}

}  // namespace
}  // namespace physdbg::peers
