// Contact begin / stay / end as a listener sees them from World::step().
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

using testbodies::ball;
using testbodies::floorSlab;

struct RecordedEvent {
  enum Kind { Begin, Stay, End } kind;
  std::uint32_t a, b;
  int step;
};

// Records every event with the number of the step (1-based) that fired it.
class RecordingListener final : public ContactListener {
 public:
  explicit RecordingListener(const World& world) : world_(world) {}
  void onContactBegin(const Contact& contact) override { record(RecordedEvent::Begin, contact.a, contact.b); }
  void onContactStay(const Contact& contact) override { record(RecordedEvent::Stay, contact.a, contact.b); }
  void onContactEnd(std::uint32_t a, std::uint32_t b) override { record(RecordedEvent::End, a, b); }

  std::vector<RecordedEvent> events;

 private:
  void record(RecordedEvent::Kind kind, std::uint32_t a, std::uint32_t b) {
    events.push_back({kind, a, b, world_.stepCount() + 1});  // fired inside the step being counted
  }
  const World& world_;
};

int count(const std::vector<RecordedEvent>& events, RecordedEvent::Kind kind) {
  int n = 0;
  for (const RecordedEvent& event : events) n += event.kind == kind;
  return n;
}

// Does the world report the contact: the narrow phase saw it touch, or the
// solver pushed on a speculative point (the impact a hair above the floor).
bool touches(const World& world) {
  if (!world.contacts().empty()) return true;
  for (const ContactManifold& manifold : world.manifolds())
    for (int p = 0; p < manifold.pointCount; ++p)
      if (manifold.points[p].normalImpulse > 0.0) return true;
  return false;
}

// Falls 1 m, rests, then is thrown upwards and watched for 15 steps, well
// before it can come back down (it rises for 3 / 9.81 s = 18 steps).
struct FallRestLift {
  std::vector<RecordedEvent> events;
  std::vector<bool> touching;  // per step: did the world report the contact
};

FallRestLift fallRestLift(bool allowSleep) {
  WorldSettings settings;
  settings.allowSleep = allowSleep;
  World world(settings);
  RecordingListener listener(world);
  world.setContactListener(&listener);
  world.addBody(floorSlab());
  const BodyId id = world.addBody(ball(Vec3(0, 1.5, 0)));
  FallRestLift run;
  for (int i = 0; i < 120; ++i) {
    world.step();
    run.touching.push_back(touches(world));
  }
  world.body(id).setLinearVelocity(Vec3(0, 3, 0));
  for (int i = 0; i < 15; ++i) {
    world.step();
    run.touching.push_back(touches(world));
  }
  run.events = listener.events;
  return run;
}

void expectBeginStaysEnd(const FallRestLift& run) {
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(count(run.events, RecordedEvent::Begin), 1);
  EXPECT_EQ(count(run.events, RecordedEvent::End), 1);
  EXPECT_EQ(run.events.front().kind, RecordedEvent::Begin);
  EXPECT_EQ(run.events.back().kind, RecordedEvent::End);
  // One stay on every touching step after the first, nothing else between.
  int touchingSteps = 0;
  for (const bool touching : run.touching) touchingSteps += touching;
  EXPECT_EQ(count(run.events, RecordedEvent::Stay), touchingSteps - 1);
  for (std::size_t i = 1; i + 1 < run.events.size(); ++i) {
    EXPECT_EQ(run.events[i].kind, RecordedEvent::Stay) << "event " << i;
    EXPECT_EQ(run.events[i].step, run.events[i - 1].step + 1) << "stays on consecutive steps";
  }
  for (const RecordedEvent& event : run.events) {
    EXPECT_EQ(event.a, 0u);
    EXPECT_EQ(event.b, 1u);
  }
  // The end comes on the first step after the lift that no longer touches.
  EXPECT_FALSE(run.touching[run.events.back().step - 1]);
  EXPECT_TRUE(run.touching[run.events.back().step - 2]);
  EXPECT_GT(run.events.back().step, 120);
}

TEST(ContactEvents, BeginOnceStayEveryTouchingStepEndOnceInOrder) {
  expectBeginStaysEnd(fallRestLift(false));
}

// Falling asleep on the ground does not separate the ball from the ground:
// the pair should neither end while the ball sleeps nor begin again when it
// wakes.
TEST(ContactEvents, SleepingOnTheGroundDoesNotEndTheContact) {
  const FallRestLift run = fallRestLift(true);
  EXPECT_EQ(count(run.events, RecordedEvent::Begin), 1);
  EXPECT_EQ(count(run.events, RecordedEvent::End), 1);
  ASSERT_FALSE(run.events.empty());
  EXPECT_GT(run.events.back().step, 120) << "the contact ended while the ball lay on the ground";
}

// Three balls land on the floor at different times: begin events of one
// step and the events of every step come in (a, b) order.
TEST(ContactEvents, SeveralPairsAreReportedInPairOrder) {
  WorldSettings settings;
  settings.allowSleep = false;
  World world(settings);
  RecordingListener listener(world);
  world.setContactListener(&listener);
  world.addBody(ball(Vec3(-3, 0.5, 0)));    // 0: already on the floor
  world.addBody(floorSlab());               // 1
  world.addBody(ball(Vec3(3, 0.5, 0)));     // 2: already on the floor
  world.addBody(ball(Vec3(0, 2.0, 0)));     // 3: lands later
  world.addBody(ball(Vec3(0.2, 3.05, 0)));  // 4: lands on ball 3
  for (int i = 0; i < 90; ++i) world.step();

  const auto& events = listener.events;
  ASSERT_FALSE(events.empty());
  for (std::size_t i = 1; i < events.size(); ++i) {
    if (events[i].step != events[i - 1].step) {
      EXPECT_GT(events[i].step, events[i - 1].step);
      continue;
    }
    const bool ordered = events[i - 1].a < events[i].a || (events[i - 1].a == events[i].a && events[i - 1].b < events[i].b);
    EXPECT_TRUE(ordered) << "step " << events[i].step << ": (" << events[i - 1].a << "," << events[i - 1].b
                         << ") before (" << events[i].a << "," << events[i].b << ")";
  }
  for (const RecordedEvent& event : events) EXPECT_LT(event.a, event.b);
  // The first step reports the two resting balls, lower pair first.
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[0].kind, RecordedEvent::Begin);
  EXPECT_EQ(events[0].a, 0u);
  EXPECT_EQ(events[0].b, 1u);
  EXPECT_EQ(events[1].a, 1u);
  EXPECT_EQ(events[1].b, 2u);
  // Every touching pair began exactly once.
  for (const auto& [a, b] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {1, 2}, {1, 3}, {3, 4}}) {
    int begins = 0;
    for (const RecordedEvent& event : events) begins += event.kind == RecordedEvent::Begin && event.a == a && event.b == b;
    EXPECT_EQ(begins, 1) << "pair (" << a << "," << b << ")";
  }
}

// Under sequential impulses a falling ball is stopped by a speculative point
// a hair above the floor, so the narrow phase never sees it touch; the
// impact still begins a contact, for every ball of `bounce` (restitution 0,
// 0.5, 0.8 and 1; body 0 is the floor), at the same first impact.
TEST(ContactEvents, EveryBounceBallBeginsTouchingTheFloorAtItsFirstImpact) {
  World world = buildWorld(resolveScene("bounce"));
  RecordingListener listener(world);
  world.setContactListener(&listener);
  for (int step = 0; step < 70; ++step) world.step();
  for (std::uint32_t ball = 1; ball <= 4; ++ball) {
    const auto begin = std::find_if(listener.events.begin(), listener.events.end(), [ball](const RecordedEvent& e) {
      return e.kind == RecordedEvent::Begin && e.a == 0 && e.b == ball;
    });
    ASSERT_NE(begin, listener.events.end()) << "ball " << ball << " never began touching the floor";
    EXPECT_GE(begin->step, 50) << "ball " << ball;
    EXPECT_LE(begin->step, 60) << "ball " << ball;
  }
}

}  // namespace
}  // namespace physdbg
