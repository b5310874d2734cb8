// Collision filters keep pairs from the narrow phase altogether; sensors
// report overlaps as events and push nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

WorldSettings settings() {
  WorldSettings world;
  world.threads = 1;
  world.allowSleep = false;
  return world;
}

TEST(CollisionFilters, FilteredPairsNeverReachTheNarrowPhase) {
  // Two balls in one column, each touching only the floor's layer: the upper
  // falls through the lower and both come to rest on the floor.
  World world(settings());
  world.addBody(testbodies::floorSlab());  // layer 1, touches all
  BodyDefinition lower = testbodies::ball(Vec3(0, 0.5, 0)), upper = testbodies::ball(Vec3(0, 1.6, 0));
  lower.filter = {0b10, 0b01};
  upper.filter = {0b100, 0b01};
  const BodyId a = world.addBody(lower), b = world.addBody(upper);
  int filtered = 0;
  for (int step = 0; step < 120; ++step) {
    world.step();
    filtered += world.lastStepStats().filteredPairs;
    for (const BodyPair& pair : world.candidatePairs()) EXPECT_FALSE(pair.a == a && pair.b == b);
    for (const ContactManifold& manifold : world.manifolds()) EXPECT_FALSE(manifold.a == a && manifold.b == b);
    EXPECT_LE(world.lastStepStats().narrowPhase.pairs, 2);  // ball-floor twice, never ball-ball
  }
  EXPECT_GT(filtered, 0);
  EXPECT_NEAR(world.body(a).position().y(), 0.5, 0.01);
  EXPECT_NEAR(world.body(b).position().y(), 0.5, 0.01);  // through the other, onto the floor
}

TEST(CollisionFilters, TheRuleIsMutual) {
  const CollisionFilter floor{0b01, ~0u}, picky{0b10, 0b10}, open{0b10, ~0u};
  EXPECT_FALSE(floor.allows(picky));  // picky does not touch layer 0
  EXPECT_FALSE(picky.allows(floor));
  EXPECT_TRUE(floor.allows(open));
  EXPECT_TRUE(open.allows(picky) && picky.allows(open));
  EXPECT_TRUE(CollisionFilter{}.isDefault());
}

struct Recorder final : ContactListener {
  int step = 0;
  std::vector<int> begins, ends;
  BodyId sensor = 0;
  void onContactBegin(const Contact& contact) override {
    if (contact.a == sensor || contact.b == sensor) begins.push_back(step);
  }
  void onContactStay(const Contact&) override {}
  void onContactEnd(std::uint32_t a, std::uint32_t b) override {
    if (a == sensor || b == sensor) ends.push_back(step);
  }
};

TEST(Sensors, ReportTheOverlapIntervalAndChangeNothingElse) {
  // A ball falls through a static sensor slab (2 m thick, 3 m up) onto the
  // floor; the same run without the sensor gives its path bit for bit.
  BodyDefinition sensor = testbodies::box(Vec3(0, 3, 0));
  sensor.collider = std::make_shared<BoxCollider>(Vec3(2, 1, 2));
  sensor.isStatic = true;
  sensor.isSensor = true;
  std::vector<Vec3> without, with;
  Recorder recorder;
  for (const bool withSensor : {false, true}) {
    World world(settings());
    world.addBody(testbodies::floorSlab());
    const BodyId ball = world.addBody(testbodies::ball(Vec3(0.3, 8, 0.2)));
    if (withSensor) {
      recorder.sensor = world.addBody(sensor);
      world.setContactListener(&recorder);
    }
    for (int step = 0; step < 150; ++step) {
      recorder.step = step;
      world.step();
      (withSensor ? with : without).push_back(world.body(ball).position());
    }
  }
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < with.size(); ++i) EXPECT_EQ(with[i], without[i]) << "step " << i;
  // The overlap, from the path: the ball's bottom below the slab's top (4 m)
  // and its top above the slab's bottom (2 m). A step's events come from the
  // contacts found at its start, at the poses the step before left: the
  // first overlapping pose begins the overlap one step later, and the first
  // pose past it ends it one step later.
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(without.size()); ++i)
    if (without[i].y() - 0.5 < 4.0 && without[i].y() + 0.5 > 2.0) {
      if (first < 0) first = i;
      last = i;
    }
  ASSERT_GE(first, 0);
  ASSERT_EQ(recorder.begins.size(), 1u);
  ASSERT_EQ(recorder.ends.size(), 1u);
  EXPECT_EQ(recorder.begins[0], first + 1);
  EXPECT_EQ(recorder.ends[0], last + 2);
}

TEST(Sensors, ADynamicSensorFallsThroughWhatItOverlaps) {
  World world(settings());
  world.addBody(testbodies::floorSlab());
  BodyDefinition ghost = testbodies::box(Vec3(0, 2, 0));
  ghost.isSensor = true;
  const BodyId id = world.addBody(ghost);
  for (int step = 0; step < 60; ++step) world.step();
  EXPECT_LT(world.body(id).position().y(), -1.0);  // through the floor: it is never pushed
  EXPECT_TRUE(world.manifolds().empty());
}

}  // namespace
}  // namespace physdbg
