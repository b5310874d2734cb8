// Contact begin / stay / end as a listener sees them: when they fire relative
// to the impact, their order, the normal and point they carry, and what
// sleeping, waking, rolling and teleporting do to them. Cases from Jolt's
// UnitTests/Physics/ContactListenerTests.cpp. Jolt's Validate callback has no
// counterpart (physdbg has no contact filter); its Add/Persist/Remove are
// physdbg's begin/stay/end.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// Jolt's release point: a radius-1 ball that, falling freely, would be
// 1e-4 m into the floor after 60 steps (cFloorHitPos = 1 - 1e-4).
double joltReleaseHeight(const WorldSettings& s) {
  const long n = 60L * flightSubsteps(s);
  return (1.0 - 1e-4) - eulerPosition(0.0, 0.0, -kGravity, substep(s), n);
}

// Jolt ContactListenerTests.cpp::TestContactListenerElastic: a radius-1 ball
// with restitution 1 falls onto the floor. Jolt: nothing before the impact,
// then Add with the floor first (lower id), normal +y (default 1e-6), both
// contact points within the penetration slop (0.02 m) of the origin; then
// only a Remove in the following second. Ours: begin exactly in the step
// whose velocity turned upward (the issue: `begin` in the step the impact
// changed velocities), floor first, normal +y within 1e-9; then stays only
// while the ball starts a step on the surface, one end, and nothing else for
// a second. The contact points are the next case.
TEST(PeerContactEvents, ElasticBallBeginsInTheImpactStepAndEndsAsItLeaves) {
  World world(settings());
  const BodyId floor = world.addBody(floorSlab());
  const BodyId ball =
      world.addBody(sphere(1.0, Vec3(0, joltReleaseHeight(world.settings()), 0), 1.0, material(1.0, 0.6)));
  RecordingListener events(world);
  int impactStep = 0;
  for (int step = 1; step <= 120 && impactStep == 0; ++step) {
    const double before = world.body(ball).linearVelocity().y();
    world.step();
    if (before < 0.0 && world.body(ball).linearVelocity().y() > 0.0) impactStep = step;
  }
  ASSERT_GT(impactStep, 0);
  measured("impact_step", impactStep);
  ASSERT_FALSE(events.events.empty());
  const RecordedEvent& begin = events.events.front();
  EXPECT_EQ(begin.kind, RecordedEvent::Begin);
  EXPECT_EQ(begin.step, impactStep);
  EXPECT_EQ(begin.a, floor);
  EXPECT_EQ(begin.b, ball);
  EXPECT_LT((begin.normal - Vec3::UnitY()).norm(), 1e-9);
  EXPECT_EQ(events.events.size(), 1u);
  events.clear();
  stepN(world, 60);
  ASSERT_EQ(events.count(RecordedEvent::End), 1);
  EXPECT_EQ(events.count(RecordedEvent::Begin), 0);
  const RecordedEvent& end = events.events.back();
  EXPECT_EQ(end.kind, RecordedEvent::End);
  EXPECT_EQ(end.a, floor);
  EXPECT_EQ(end.b, ball);
  EXPECT_LE(end.step, impactStep + 2);
  EXPECT_EQ(events.count(RecordedEvent::Stay), end.step - impactStep - 1);
  measured("steps_from_begin_to_end", end.step - impactStep);
}

// The same impact, Jolt's check of where the Add's contact points lie: on
// the floor under the ball, within the penetration slop (0.02 m) of the
// origin. Engine-neutral: the points where the bodies meet, the origin.
// Ours: within 2e-3 m of it.
// Failed while a speculative impact was reported at the start of its step:
// the begin carried the ball's point 0.162 m above the origin.
TEST(PeerContactEvents, ImpactBeginCarriesThePointWhereTheBodiesMeet) {
  World world(settings());
  world.addBody(floorSlab());
  world.addBody(sphere(1.0, Vec3(0, joltReleaseHeight(world.settings()), 0), 1.0, material(1.0, 0.6)));
  RecordingListener events(world);
  for (int step = 1; step <= 120 && events.events.empty(); ++step) world.step();
  ASSERT_FALSE(events.events.empty());
  const RecordedEvent& begin = events.events.front();
  ASSERT_EQ(begin.kind, RecordedEvent::Begin);
  measured("point_distance_from_origin_m", std::max(begin.pointA.norm(), begin.pointB.norm()));
  EXPECT_LT(begin.pointA.norm(), 2e-3);
  EXPECT_LT(begin.pointB.norm(), 2e-3);
}

// Jolt ContactListenerTests.cpp::TestContactListenerInelastic: a radius-1
// ball with restitution 0 lands, lies still for 10 steps (10 Persists, at
// the floor within the slop), sleeps, is woken, rolls for 10 steps (10
// Persists, contact points within the slop of the floor plane), and is
// teleported back up (one Remove). Jolt removes the contact when the ball
// falls asleep and adds it again when it wakes; physdbg keeps a sleeping
// contact (scenes/README.md: sleeping does not end a contact, waking does
// not begin it), the engine-neutral answer for a ball that never left the
// floor. Ours: one begin; a stay on each of the 10 steps; no event while
// asleep and no begin on waking; 10 stays while rolling with points within
// 2e-3 m of the plane and normal +y within 1e-9; one end on the teleport
// step; the centre within the contact's resting depth plus 1e-6 m of y = 1.
TEST(PeerContactEvents, InelasticBallKeepsItsContactThroughSleepWakeAndRolling) {
  World world(settings(1.0 / 60.0, true));
  const BodyId floor = world.addBody(floorSlab());
  const double release = joltReleaseHeight(world.settings());
  const BodyId ball = world.addBody(sphere(1.0, Vec3(0, release, 0), 1.0, material(0.0, 0.6)));
  RecordingListener events(world);
  const double omega = 2.0 * std::numbers::pi * world.settings().solver.contactHertz;
  const double depth = kGravity / (omega * omega);
  const auto expectOnTheFloor = [&](const char* when) {
    const double y = world.body(ball).position().y();
    EXPECT_LE(y, 1.0 + 1e-6) << when;
    EXPECT_GE(y, 1.0 - depth - 1e-6) << when;
  };
  for (int step = 1; step <= 120 && events.events.empty(); ++step) world.step();
  ASSERT_EQ(events.count(RecordedEvent::Begin, floor, ball), 1);
  EXPECT_LT(world.body(ball).linearVelocity().norm(), 1e-5);
  expectOnTheFloor("after the impact");
  events.clear();

  stepN(world, 10);
  EXPECT_EQ(events.count(RecordedEvent::Stay, floor, ball), 10);
  EXPECT_EQ(events.events.size(), 10u);
  expectOnTheFloor("after 10 steps");
  events.clear();

  int steps = 0;
  while (!world.isAsleep(ball) && steps < 120) {
    world.step();
    ++steps;
  }
  ASSERT_TRUE(world.isAsleep(ball));
  measured("steps_to_sleep", steps);
  const std::size_t beforeSleep = events.events.size();
  EXPECT_EQ(events.count(RecordedEvent::Stay), static_cast<int>(beforeSleep));
  stepN(world, 30);
  EXPECT_EQ(events.events.size(), beforeSleep) << "events while asleep";
  expectOnTheFloor("asleep");
  events.clear();

  world.wake(ball);
  world.step();
  EXPECT_EQ(events.count(RecordedEvent::Begin), 0) << "waking began the contact again";
  EXPECT_EQ(events.count(RecordedEvent::End), 0);
  events.clear();

  world.body(ball).setLinearVelocity(Vec3(1, 0, 0));
  stepN(world, 10);
  EXPECT_EQ(events.count(RecordedEvent::Stay, floor, ball), 10);
  EXPECT_EQ(events.events.size(), 10u);
  double worstPoint = 0.0;
  for (const RecordedEvent& event : events.events) {
    EXPECT_LT((event.normal - Vec3::UnitY()).norm(), 1e-9);
    worstPoint = std::max({worstPoint, std::abs(event.pointA.y()), std::abs(event.pointB.y())});
  }
  measured("rolling_point_height_m", worstPoint);
  EXPECT_LT(worstPoint, 2e-3);
  events.clear();

  world.scheduleState({ball, world.stepCount(), Vec3(0, release, 0), std::nullopt, std::nullopt, std::nullopt});
  stepN(world, 10);
  EXPECT_EQ(events.count(RecordedEvent::End, floor, ball), 1);
  EXPECT_EQ(events.events.size(), 1u);
  if (!events.events.empty()) {
    EXPECT_EQ(events.events.front().step, world.stepCount() - 9);
  }
}

}  // namespace
}  // namespace physdbg::peers
