// Fast bodies, straight and angled: boxes that travel two metres a step into
// each other, into sleeping boxes and into a row of sleepers, and balls fired
// at a thin wall. Cases from Jolt's UnitTests/Physics/
// MotionQualityLinearCastTests.cpp and PhysicsTests.cpp
// (TestPhysicsActivateDuringStep), and Box2D v3's test/test_world.c
// (TestSensor's bullet). Jolt's Discrete bodies tunnel by design and its
// LinearCast bodies stop where the cast hits; physdbg has one motion quality
// (speculative contacts), and the engine-neutral answer replaces both: no
// body passes through another, momentum is conserved, and a body is never
// further along than the exact impact would put it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

constexpr double kFrequency = 60.0;
constexpr double kSpeed = 2.0 * kFrequency;  // 2 m a step

struct TwoBoxes {
  World world;
  BodyId first = 0, second = 0;
};

TwoBoxes twoBoxes(const Vec3& firstPosition, const Vec3& firstVelocity, const Vec3& secondPosition,
                  const Vec3& secondVelocity, double restitution, bool secondAsleep, double friction = 0.6,
                  bool cast = true) {
  WorldSettings s = weightless(1.0 / kFrequency);
  s.allowSleep = true;
  s.castFastPairs = cast;
  TwoBoxes scene{World(s), 0, 0};
  BodyDefinition a = box(Vec3::Constant(0.5), firstPosition, 1.0, material(restitution, friction));
  a.linearVelocity = firstVelocity;
  scene.first = scene.world.addBody(a);
  BodyDefinition b = box(Vec3::Constant(0.5), secondPosition, 1.0, material(restitution, friction));
  b.linearVelocity = secondVelocity;
  scene.second = scene.world.addBody(b);
  if (secondAsleep) scene.world.sleep(scene.second);
  return scene;
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsLinearCastBoxInelastic
// (and TestDiscreteBoxVsDiscreteBox, where Jolt's discrete boxes pass through
// each other): unit boxes 1 m apart closing at 2 m a step each, restitution
// 0. Jolt: after the step both at rest (1e-6) at x = -0.5 and 0.5 within the
// slop (0.02 m), no spin; Persist for 10 steps. Ours: speed below 1e-9 m/s,
// spin below 1e-9 rad/s, faces touching at x = 0 within 1e-9 m (no load,
// nothing to sink them); begin, then a stay on each of 10 steps.
TEST(PeerFastBodies, HeadOnBoxesAtTwoMetresAStepStopEachOther) {
  TwoBoxes scene = twoBoxes(Vec3(-1, 0, 0), Vec3(kSpeed, 0, 0), Vec3(1, 0, 0), Vec3(-kSpeed, 0, 0), 0.0, false);
  RecordingListener events(scene.world);
  double worstPosition = 0.0, worstSpeed = 0.0;
  for (int step = 1; step <= 11; ++step) {
    scene.world.step();
    for (const BodyId id : {scene.first, scene.second}) {
      const RigidBody& body = scene.world.body(id);
      const double expectedX = id == scene.first ? -0.5 : 0.5;
      EXPECT_NEAR(body.position().x(), expectedX, 1e-9) << "step " << step;
      EXPECT_LT(body.linearVelocity().norm(), 1e-9) << "step " << step;
      EXPECT_LT(body.angularVelocity().norm(), 1e-9) << "step " << step;
      worstPosition = std::max(worstPosition, std::abs(body.position().x() - expectedX));
      worstSpeed = std::max(worstSpeed, body.linearVelocity().norm());
    }
  }
  measured("worst_position_error_m", worstPosition);
  measured("worst_speed_mps", worstSpeed);
  EXPECT_EQ(events.count(RecordedEvent::Begin), 1);
  EXPECT_EQ(events.count(RecordedEvent::Stay), 10);
  EXPECT_EQ(events.events.size(), 11u);
  if (!events.events.empty()) {
    EXPECT_EQ(events.events.front().step, 1);
  }
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsLinearCastBoxElastic:
// as above with restitution 1. Jolt: velocities reversed (1e-6), boxes at
// x = -/+0.5 within the slop after the step (where its cast stopped them),
// then 2 m apart a step. The exact impact, a quarter of the way into the
// step, leaves them at -/+2 m; a solver that bounces at the end of the step
// leaves them at -/+0.5. Ours: velocities within 1e-9 m/s of the reversed
// ones, no spin (1e-9 rad/s), the first box in [-2, -0.5] (1e-9 m) and
// symmetric with the second, then 2 m further each step exactly (1e-9 m);
// begin in step 1, end by step 3.
TEST(PeerFastBodies, HeadOnElasticBoxesReverseWithoutPassingThrough) {
  TwoBoxes scene = twoBoxes(Vec3(-1, 0, 0), Vec3(kSpeed, 0, 0), Vec3(1, 0, 0), Vec3(-kSpeed, 0, 0), 1.0, false);
  RecordingListener events(scene.world);
  scene.world.step();
  const RigidBody &a = scene.world.body(scene.first), &b = scene.world.body(scene.second);
  const double error =
      std::max((a.linearVelocity() - Vec3(-kSpeed, 0, 0)).norm(), (b.linearVelocity() - Vec3(kSpeed, 0, 0)).norm());
  measured("velocity_error_mps", error);
  measured("first_box_x_after_step_1_m", a.position().x());
  EXPECT_LT(error, 1e-9);
  EXPECT_LT(std::max(a.angularVelocity().norm(), b.angularVelocity().norm()), 1e-9);
  EXPECT_GE(a.position().x(), -2.0 - 1e-9);
  EXPECT_LE(a.position().x(), -0.5 + 1e-9);
  EXPECT_NEAR(a.position().x(), -b.position().x(), 1e-9);
  const double x1 = a.position().x();
  scene.world.step();
  scene.world.step();
  EXPECT_NEAR(scene.world.body(scene.first).position().x(), x1 - 4.0, 1e-9);
  EXPECT_EQ(events.count(RecordedEvent::Begin), 1);
  EXPECT_EQ(events.count(RecordedEvent::End), 1);
  if (!events.events.empty()) {
    EXPECT_EQ(events.events.front().step, 1);
  }
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsInactiveLinearCastBox
// and ::TestLinearCastBoxVsInactiveDiscreteBox: a box at 2 m a step meets a
// sleeping one 1 m away, restitution 0. Jolt: the sleeper wakes, both move at
// half the speed (1e-6), the sleeper has not moved in the step (its cast
// order), the first touches it within the slop; next step both 1 m further.
// The exact impact, half way into the step, moves the sleeper 0.5 m in the
// step; so the engine-neutral answer allows it anywhere in [1, 1.5], the
// first box touching it. Ours: both at 60 m/s within 1e-9, momentum exact to
// 1e-12 relative, touching within 1e-9 m, then 1 m further (1e-9 m) the next
// step; the sleeper awake; begin in step 1.
TEST(PeerFastBodies, FastBoxSharesItsMomentumWithASleepingBox) {
  TwoBoxes scene = twoBoxes(Vec3(-1, 0, 0), Vec3(kSpeed, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), 0.0, true);
  ASSERT_TRUE(scene.world.isAsleep(scene.second));
  RecordingListener events(scene.world);
  scene.world.step();
  const RigidBody &a = scene.world.body(scene.first), &b = scene.world.body(scene.second);
  EXPECT_FALSE(scene.world.isAsleep(scene.second));
  const double half = 0.5 * kSpeed;
  const double error = std::max(std::abs(a.linearVelocity().x() - half), std::abs(b.linearVelocity().x() - half));
  measured("velocity_error_mps", error);
  measured("sleeper_x_after_step_1_m", b.position().x());
  EXPECT_LT(error, 1e-9);
  EXPECT_NEAR(a.linearVelocity().x() + b.linearVelocity().x(), kSpeed, 1e-12 * kSpeed);
  EXPECT_GE(b.position().x(), 1.0 - 1e-9);
  EXPECT_LE(b.position().x(), 1.5 + 1e-9);
  EXPECT_NEAR(b.position().x() - a.position().x(), 1.0, 1e-9);
  EXPECT_EQ(events.count(RecordedEvent::Begin, scene.first, scene.second), 1);
  const double x1 = b.position().x();
  scene.world.step();
  EXPECT_NEAR(scene.world.body(scene.second).position().x(), x1 + 1.0, 1e-9);
  EXPECT_NEAR(scene.world.body(scene.first).position().x(), x1, 1e-9);
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsInactiveDiscreteBoxAngled:
// a frictionless elastic box flies at (-120, 0, 240) m/s onto the +x face of
// a sleeping one, hitting its centre. Equal masses along the normal x swap
// their x speeds; the z speed is untouched. Jolt: (0, 0, 240) and (-120, 0,
// 0) within 1e-4 m/s, spin within 2e-4 rad/s, the sleeper awake. Ours: 1e-5
// m/s and 2e-5 rad/s (ten times tighter), the flying box never on the
// sleeper's side of its face (1e-9 m).
// Failed before fast pairs were cast to their time of impact: the normal of
// the start-of-step closest features (a diagonal edge pair) gave a velocity
// error of 91.67 m/s, 150.5 rad/s of spin, and the boxes ended the step
// 0.211 m into each other.
TEST(PeerFastBodies, AngledHitOnASleepingBoxPassesOnOnlyTheNormalSpeed) {
  const Vec3 offset(1, 0, -2);
  const Vec3 velocity = -kFrequency * 2.0 * offset;
  TwoBoxes scene = twoBoxes(Vec3(1, 0, 0) + offset, velocity, Vec3::Zero(), Vec3::Zero(), 1.0, true, 0.0);
  scene.world.step();
  const RigidBody &a = scene.world.body(scene.first), &b = scene.world.body(scene.second);
  const double error = std::max((a.linearVelocity() - Vec3(0, 0, velocity.z())).norm(),
                                (b.linearVelocity() - Vec3(velocity.x(), 0, 0)).norm());
  const double spin = std::max(a.angularVelocity().norm(), b.angularVelocity().norm());
  measured("velocity_error_mps", error);
  measured("spin_rad_s", spin);
  EXPECT_FALSE(scene.world.isAsleep(scene.second));
  EXPECT_LT(error, 1e-5);
  EXPECT_LT(spin, 2e-5);
  EXPECT_GE(a.position().x() - b.position().x(), 1.0 - 1e-9);
}

// The same throw with time_of_impact off (WorldSettings::castFastPairs):
// the start-of-step features' diagonal normal, so the sleeper is pushed
// along z too. Checks that the setting is what makes the answer above.
TEST(PeerFastBodies, AngledHitWithoutTheCastTakesTheStartOfStepNormal) {
  const Vec3 offset(1, 0, -2);
  const Vec3 velocity = -kFrequency * 2.0 * offset;
  TwoBoxes scene = twoBoxes(Vec3(1, 0, 0) + offset, velocity, Vec3::Zero(), Vec3::Zero(), 1.0, true, 0.0, false);
  scene.world.step();
  const RigidBody& b = scene.world.body(scene.second);
  measured("sleeper_z_speed_mps", b.linearVelocity().z());
  EXPECT_GT(std::abs(b.linearVelocity().z()), 1.0);
}

// Jolt MotionQualityLinearCastTests.cpp::TestLinearCastBoxVsSlowDiscreteBox:
// a box at 120 m/s meets one coming at -6 m/s, restitution 0: both leave at
// (120 - 6) / 2 = 57 m/s. Jolt: 1e-6 (positions within the slop). Ours:
// 1e-9 m/s, momentum to 1e-12 relative, touching within 1e-9 m.
TEST(PeerFastBodies, FastBoxMeetsASlowBoxAndBothMoveOnTogether) {
  const double slow = -0.1 * kFrequency;
  TwoBoxes scene = twoBoxes(Vec3(-1, 0, 0), Vec3(kSpeed, 0, 0), Vec3(1, 0, 0), Vec3(slow, 0, 0), 0.0, false);
  scene.world.step();
  const RigidBody &a = scene.world.body(scene.first), &b = scene.world.body(scene.second);
  const double common = 0.5 * (kSpeed + slow);
  const double error = std::max(std::abs(a.linearVelocity().x() - common), std::abs(b.linearVelocity().x() - common));
  measured("velocity_error_mps", error);
  EXPECT_LT(error, 1e-9);
  EXPECT_NEAR(a.linearVelocity().x() + b.linearVelocity().x(), kSpeed + slow, 1e-12 * kSpeed);
  EXPECT_NEAR(b.position().x() - a.position().x(), 1.0, 1e-9);
}

// Jolt PhysicsTests.cpp::TestPhysicsActivateDuringStep: ten sleeping unit
// boxes in a row, each overlapping the next by Jolt's slop (0.02 m), created
// in order and in reverse; the first is given 500 m/s (8.3 m a step, through
// the second in one step if nothing stops it). Jolt: after one step all are
// awake, each pair of neighbours (and only those) reported, each box right
// of where it started, none past its right neighbour. Ours: the same, plus
// the row's momentum 500 kg m/s conserved to 1e-9 relative.
TEST(PeerFastBodies, FastBoxWakesARowOfSleepersAndNoneTunnels) {
  for (const bool reverse : {false, true}) {
    SCOPED_TRACE(reverse ? "reverse" : "in order");
    WorldSettings s = weightless();
    s.allowSleep = true;
    World world(s);
    const int count = 10;
    const double spacing = 1.0 - 0.02;
    std::vector<BodyId> row(count);
    for (int k = 0; k < count; ++k) {
      const int i = reverse ? count - 1 - k : k;
      row[i] = world.addBody(box(Vec3::Constant(0.5), Vec3(i * spacing, 0, 0)));
    }
    for (BodyId id : row) world.sleep(id);
    world.body(row[0]).setLinearVelocity(Vec3(500, 0, 0));
    RecordingListener events(world);
    world.step();
    double momentum = 0.0;
    for (int i = 0; i < count; ++i) {
      EXPECT_FALSE(world.isAsleep(row[i])) << "box " << i;
      EXPECT_GT(world.body(row[i]).position().x(), i * spacing) << "box " << i;
      if (i > 0) {
        EXPECT_LT(world.body(row[i - 1]).position().x(), world.body(row[i]).position().x()) << "box " << i;
      }
      momentum += world.body(row[i]).linearVelocity().x();
    }
    EXPECT_NEAR(momentum, 500.0, 1e-9 * 500.0);
    EXPECT_EQ(events.count(RecordedEvent::Begin), count - 1);
    for (const RecordedEvent& event : events.events) {
      const auto ia = std::find(row.begin(), row.end(), event.a) - row.begin();
      const auto ib = std::find(row.begin(), row.end(), event.b) - row.begin();
      EXPECT_EQ(std::abs(ia - ib), 1) << "pair " << event.a << ", " << event.b;
    }
    if (!reverse) measured("row_momentum_kg_mps", momentum);
  }
}

// Box2D test_world.c::TestSensor fires a radius-0.1 bullet at -20 m/s at a
// wall (there a sensor: one begin, one end). physdbg has no sensors; the
// same shot at a solid, thin (0.1 m) static wall at 20, 200 and 2000 m/s,
// straight and at 45 degrees, restitution 0, no gravity: the ball must never
// be found inside or beyond the wall, and ends at rest against it. Box2D's
// figure is the event count; ours: the ball's surface never past the wall's
// face by more than 1e-9 m on any step, and its normal speed 0 within 1e-9
// m/s after the hit.
TEST(PeerFastBodies, BallsFiredAtAThinWallNeverCrossIt) {
  double deepest = 0.0;
  for (const double speed : {20.0, 200.0, 2000.0})
    for (const double angle : {0.0, 45.0}) {
      SCOPED_TRACE(speed);
      SCOPED_TRACE(angle);
      World world(weightless());
      BodyDefinition wall = box(Vec3(0.05, 50.0, 50.0), Vec3(1.5, 0, 0));
      wall.isStatic = true;
      world.addBody(wall);
      const double radians = angle * std::numbers::pi / 180.0;
      BodyDefinition ball = sphere(0.1, Vec3(7.4, 0, 0), 1.0, material(0.0, 0.0));
      ball.linearVelocity = Vec3(-std::cos(radians), std::sin(radians), 0) * speed;
      const BodyId id = world.addBody(ball);
      const double face = 1.55;
      for (int i = 0; i < 60; ++i) {
        world.step();
        const double depth = face - (world.body(id).position().x() - 0.1);
        deepest = std::max(deepest, depth);
        ASSERT_LE(depth, 1e-9) << "step " << i + 1;
      }
      EXPECT_NEAR(world.body(id).linearVelocity().x(), 0.0, 1e-9);
    }
  measured("deepest_m", deepest);
}

}  // namespace
}  // namespace physdbg::peers
