// Friction: a box sliding to a stop, a box spinning down on its corners,
// boxes on slopes below and above the friction angle (as JSON scenes loaded
// with the scenes library), a box settling on the ground, and a ball that
// slides, starts rolling and rolls on. Cases from Jolt's
// UnitTests/Physics/PhysicsTests.cpp (TestFriction, TestAngularFriction) and
// ContactListenerTests.cpp (the rolling sphere), Bullet's
// test/RobotClientAPI/SlopeFrictionMain.cpp and Box2D v3's test/test_world.c
// (HelloWorld). Coulomb friction under the engine's substeps: a sliding body
// loses mu g h of speed on each substep, so after N substeps v = v0 - mu g N h
// and x = v0 N h - mu g h^2 N (N + 1) / 2, exactly as free fall.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// A box of half extent 1 resting on Jolt's floor with friction `mu` on both
// (static = dynamic, so the answer has one coefficient), sliding at v0.
struct Slider {
  World world;
  BodyId box = 0;
};

Slider slider(const Vec3& velocity, double muFloor, double muBox) {
  Slider scene{World(settings()), 0};
  scene.world.addBody(floorSlab(0.0, 200.0, material(0.0, muFloor)));
  BodyDefinition def = box(Vec3::Ones(), Vec3(0, 1.0, 0), 1.0, material(0.0, muBox));
  def.linearVelocity = velocity;
  scene.box = scene.world.addBody(def);
  return scene;
}

// Semi-implicit Euler of a body decelerating at `deceleration` along x, on
// the substeps each step of `world` took (a box sliding alone on the floor
// is a calm island: calmSubsteps), stopping at zero speed.
struct Reference {
  double x = 0.0, v = 0.0;
  void step(const World& world, double deceleration) {
    const int count = world.lastStepStats().substeps;
    const double h = world.settings().dt / count;
    for (int i = 0; i < count; ++i) {
      v = std::max(0.0, v - deceleration * h);
      x += v * h;
    }
  }
};

// Jolt PhysicsTests.cpp::TestFriction: a box of half extent 1 slides at 20
// m/s over the floor in 12 directions, friction 0.9 (floor) and 0.8 (box),
// combined sqrt(0.9 x 0.8) (physdbg's default rule too). Jolt compares 60
// steps with its own Euler integration of a deceleration mu g: position
// within 1e-2 m, velocity 2e-2 m/s, rotation and spin 1e-2. Ours: against
// the same integration on the engine's substeps, 1e-3 m, 2e-3 m/s, 1e-3 rad
// and 1e-3 rad/s (ten times tighter); the box no higher than the floor and
// no deeper in it than twice the contact's resting depth g / (2 pi f)^2.
TEST(PeerFriction, SlidingBoxDeceleratesAtMuG) {
  const double mu = std::sqrt(0.9 * 0.8), v0 = 20.0;
  double worstPosition = 0.0, worstVelocity = 0.0, worstRotation = 0.0;
  for (int degrees = 0; degrees < 360; degrees += 30) {
    SCOPED_TRACE(degrees);
    const double angle = degrees * std::numbers::pi / 180.0;
    const Vec3 direction(std::sin(angle), 0, std::cos(angle));
    Slider scene = slider(direction * v0, 0.9, 0.8);
    Reference reference{0.0, v0};
    for (int i = 0; i < 60; ++i) {
      scene.world.step();
      reference.step(scene.world, mu * kGravity);
    }
    const double omega = 2.0 * std::numbers::pi * scene.world.settings().solver.contactHertz;
    const RigidBody& body = scene.world.body(scene.box);
    const Vec3 horizontal(body.position().x(), 0.0, body.position().z());
    const double positionError = (horizontal - direction * reference.x).norm();
    const double velocityError = (body.linearVelocity() - direction * reference.v).norm();
    const double rotation = std::max(angleBetween(body.orientation(), Quat::Identity()), body.angularVelocity().norm());
    EXPECT_LT(positionError, 1e-3);
    EXPECT_LT(velocityError, 2e-3);
    EXPECT_LT(rotation, 1e-3);
    EXPECT_LE(body.position().y(), 1.0);
    EXPECT_GE(body.position().y(), 1.0 - 2.0 * kGravity / (omega * omega));
    worstPosition = std::max(worstPosition, positionError);
    worstVelocity = std::max(worstVelocity, velocityError);
    worstRotation = std::max(worstRotation, rotation);
  }
  measured("worst_position_error_m", worstPosition);
  measured("worst_velocity_error_mps", worstVelocity);
  measured("worst_rotation_or_spin", worstRotation);
}

// TestFriction run to the end: the box stops after v0^2 / (2 mu g) (24.03 m
// from 20 m/s with mu = 0.849), less the integrator's known offset v0 h / 2
// (semi-implicit Euler on substeps of h; 0.042 m here), and stays. No peer
// tolerance (Jolt stops at 60 steps). Ours: within 1e-4 m (the last substep
// stops part way: at most mu g h^2), speed below 1e-6 m/s a second later.
TEST(PeerFriction, SlidingBoxStopsAfterVSquaredOverTwoMuG) {
  const double mu = std::sqrt(0.9 * 0.8), v0 = 20.0;
  Slider scene = slider(Vec3(v0, 0, 0), 0.9, 0.8);
  scene.world.step();
  const double h = scene.world.settings().dt / scene.world.lastStepStats().substeps;
  stepN(scene.world, 239);
  const double distance = scene.world.body(scene.box).position().x();
  const double expected = v0 * v0 / (2.0 * mu * kGravity) - 0.5 * v0 * h;
  measured("stopping_distance_m", distance);
  measured("expected_m", expected);
  EXPECT_NEAR(distance, expected, 1e-4);
  EXPECT_LT(scene.world.body(scene.box).linearVelocity().norm(), 1e-6);
}

// Jolt PhysicsTests.cpp::TestAngularFriction: a box of half extent 1 spins
// at 10 rad/s about y on the floor, friction 0.2 and 0.3 (mu = 0.245). With
// its weight on the four corners (the contact points every engine here
// uses), friction brakes it with the torque mu m g sqrt(2), so omega falls
// by mu m g sqrt(2) / I_yy per second. Jolt: 60 steps against that, position
// within 1e-4 m, rotation 2e-3 rad, velocity 4e-4 m/s, spin 5e-3 rad/s.
// Ours: 1e-5 m, 2e-4 rad, 4e-5 m/s and 5e-4 rad/s (ten times tighter); the
// height is the floor's less the contact's resting depth.
// The reference integrates with the substeps the box actually takes (a box
// resting alone takes the calm 4, not 8).
// Failed while sliding friction took the two tangent rows' joint update: the
// rows' unequal masses turned it off the sliding direction and the corner
// torque came out 1.35% weak (spin 4.9713 rad/s after 1 s against 4.9026).
TEST(PeerFriction, SpinningBoxSlowsByItsCornerFrictionTorque) {
  const double mu = std::sqrt(0.2 * 0.3);
  World world(settings());
  world.addBody(floorSlab(0.0, 100.0, material(0.0, 0.2)));
  BodyDefinition def = box(Vec3::Ones(), Vec3(10, 1.0, 10), 1.0, material(0.0, 0.3));
  def.angularVelocity = Vec3(0, 10, 0);
  const BodyId id = world.addBody(def);
  const double inertia = world.body(id).localInertia()(1, 1);
  const double deceleration = mu * kGravity * std::sqrt(2.0) / inertia;
  double spin = 10.0, angle = 0.0;
  for (int step = 0; step < 60; ++step) {
    world.step();
    const int substeps = world.lastStepStats().substeps;
    const double h = world.settings().dt / substeps;
    for (int k = 0; k < substeps; ++k) {
      spin -= deceleration * h;
      angle += spin * h;
    }
  }
  const RigidBody& body = world.body(id);
  const double spinError = (body.angularVelocity() - Vec3(0, spin, 0)).norm();
  const double rotationError = angleBetween(body.orientation(), Quat(Eigen::AngleAxisd(angle, Vec3::UnitY())));
  measured("spin_rad_s", body.angularVelocity().y());
  measured("expected_spin_rad_s", spin);
  measured("rotation_error_rad", rotationError);
  EXPECT_GE(body.angularVelocity().y(), 0.0);
  EXPECT_LT(body.angularVelocity().y(), 5.0);
  const double omega = 2.0 * std::numbers::pi * world.settings().solver.contactHertz;
  EXPECT_LT((body.position() - Vec3(10, 1.0 - kGravity / (omega * omega), 10)).norm(), 1e-5);
  EXPECT_LT(body.linearVelocity().norm(), 4e-5);
  EXPECT_LT(spinError, 5e-4);
  EXPECT_LT(rotationError, 2e-4);
}

// The issue's case: the corner model for any box, flat to tall (the same
// four corners carry the weight whatever the height): omega falls at
// 3 mu g / sqrt(hx^2 + hz^2). No peer tolerance; Jolt's TestAngularFriction
// allows 5e-3 rad/s. Ours: the fall from step 5 to step 20 (the soft
// contact has taken the whole weight by then; in the first steps it is still
// settling and holds a little less) within 1e-3 of the model's, with the
// reference integrated over the substeps each step took.
// Failed while sliding friction took the rows' joint update: 1.4% (tall) to
// 4.9% (flat) short of the model.
TEST(PeerFriction, SpinningBoxesOfAnyShapeSlowByTheirCornerFrictionTorque) {
  const double mu = 0.5;
  double worst = 0.0;
  for (const Vec3& half : {Vec3(0.5, 0.1, 0.5), Vec3(0.5, 1.0, 0.5), Vec3(1.0, 0.2, 0.4)}) {
    SCOPED_TRACE(half.transpose());
    World world(settings());
    world.addBody(floorSlab(0.0, 100.0, material(0.0, mu)));
    BodyDefinition def = box(half, Vec3(0, half.y(), 0), 1.0, material(0.0, mu));
    def.angularVelocity = Vec3(0, 12, 0);
    const BodyId id = world.addBody(def);
    stepN(world, 5);
    const double deceleration = 3.0 * mu * kGravity / std::hypot(half.x(), half.z());
    const double start = world.body(id).angularVelocity().y();
    stepN(world, 15);
    const double expected = deceleration * 15.0 * world.settings().dt;
    const double error = std::abs((start - world.body(id).angularVelocity().y()) - expected) / expected;
    worst = std::max(worst, error);
    EXPECT_GT(world.body(id).angularVelocity().y(), 0.0);
    EXPECT_LT(error, 1e-3);
  }
  measured("worst_relative_error", worst);
}

// A unit box on a static slab tilted by `degrees` about z, written as a
// scene file (scenes/README.md) and loaded with the scenes library.
World slopeScene(double degrees, double friction) {
  const double angle = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(angle / 2.0), s = std::sin(angle / 2.0);
  // The box sits on the slab's top face, centre 0.5 m above it.
  const Vec3 normal(-std::sin(angle), std::cos(angle), 0);
  const Vec3 centre = normal * 0.5;
  char json[2048];
  std::snprintf(json, sizeof json, R"({
    "name": "slope", "dt": 0.016666666666666666, "allow_sleep": false,
    "bodies": [
      {"shape": {"box": {"half_extents": [20, 1, 5]}}, "position": [%.17g, %.17g, 0],
       "orientation": [%.17g, 0, 0, %.17g], "static": true,
       "static_friction": %.17g, "dynamic_friction": %.17g},
      {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [%.17g, %.17g, 0],
       "orientation": [%.17g, 0, 0, %.17g], "mass": 1,
       "static_friction": %.17g, "dynamic_friction": %.17g}
    ]})",
                -normal.x(), -normal.y(), c, s, friction, friction, centre.x(), centre.y(), c, s, friction, friction);
  return sceneWorld(json, "slope.json");
}

// Bullet test/RobotClientAPI/SlopeFrictionMain.cpp puts a cube on a plane
// tilted by 0.23 pi (41.4 degrees) and only shows it (no assertion). The
// analytic answer: with tan(theta) < mu the box stays. At 20 degrees and mu
// = 0.6 (tan = 0.364) ours: the box moves less than 1e-5 m along the slope
// in 2 s and ends slower than 1e-5 m/s. (The box starts on the surface.)
TEST(PeerFriction, BoxOnASlopeBelowTheFrictionAngleStays) {
  World world = slopeScene(20.0, 0.6);
  stepN(world, 30);  // settles into the contact's resting depth
  const Vec3 start = world.body(1).position();
  stepN(world, 120);
  const double moved = (world.body(1).position() - start).norm();
  measured("creep_m", moved);
  EXPECT_LT(moved, 1e-5);
  EXPECT_LT(world.body(1).linearVelocity().norm(), 1e-5);
}

// Bullet's slope at 0.23 pi with mu = 0.5 < tan(41.4 deg) = 0.88: the box
// slides with a = g (sin - mu cos) = 2.81 m/s^2 and does not tip. Ours: the
// speed along the slope after 1 s within 1e-4 of a t relative (the speed
// grows by a h on each substep, exactly), and the box tilted off the slope
// by less than the two contact depths apart over its width allow (2 g /
// (2 pi f)^2 / 1 m = 1.4e-4 rad).
TEST(PeerFriction, BoxOnASlopeAboveTheFrictionAngleSlidesAtGSinMinusMuCos) {
  const double degrees = 0.23 * 180.0, mu = 0.5;
  const double angle = degrees * std::numbers::pi / 180.0;
  World world = slopeScene(degrees, mu);
  stepN(world, 60);
  const Vec3 downhill(-std::cos(angle), -std::sin(angle), 0);
  const double speed = world.body(1).linearVelocity().dot(downhill);
  const double expected = kGravity * (std::sin(angle) - mu * std::cos(angle)) * 1.0;
  measured("speed_mps", speed);
  measured("expected_mps", expected);
  const double omega = 2.0 * std::numbers::pi * world.settings().solver.contactHertz;
  const double tilt = angleBetween(world.body(1).orientation(), Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ())));
  measured("tilt_rad", tilt);
  EXPECT_NEAR(speed, expected, 1e-4 * expected);
  EXPECT_LT(tilt, 2.0 * kGravity / (omega * omega));
}

// Box2D test_world.c::HelloWorld: a box of half extent 1 (friction 0.3)
// dropped from y = 4 onto the ground (gravity 10), 90 steps. Box2D: x within
// 0.01, y within 0.01 of 1, angle within 0.01. Ours: 0.001 each.
TEST(PeerFriction, HelloWorldBoxSettlesOnTheGround) {
  WorldSettings s = settings();
  s.gravity = Vec3(0, -10, 0);
  World world(s);
  world.addBody(floorSlab(0.0, 50.0));
  const BodyId id = world.addBody(box(Vec3::Ones(), Vec3(0, 4, 0), 4.0, material(0.0, 0.3)));
  stepN(world, 90);
  const RigidBody& body = world.body(id);
  measured("y_m", body.position().y());
  EXPECT_LT(std::abs(body.position().x()), 0.001);
  EXPECT_LT(std::abs(body.position().y() - 1.0), 0.001);
  EXPECT_LT(angleBetween(body.orientation(), Quat::Identity()), 0.001);
}

// The rolling sphere of Jolt ContactListenerTests.cpp::TestContactListenerInelastic,
// given 5 m/s on a floor of friction 0.5 without spin: friction at the
// contact point has no moment about it, so m v r + I w about the floor is
// kept while it slides, and it rolls on at 5/7 v0 with w = v / r. No peer
// tolerance (Jolt counts events there). Ours: 5/7 v0 within 1e-6 relative,
// rolling (v - w r) within 1e-6 m/s after 1 s.
// Fails today: 3.571297 m/s (1.3e-4 short of 3.571429) and still slipping at
// -2.47e-4 m/s (it spins faster than it rolls): the soft contact holds the
// ball 7e-5 m deep and friction acts at the middle of the overlap, so it
// rolls on a radius 3.5e-5 m short.
TEST(PeerFriction, DISABLED_SlidingBallEndsRollingAtFiveSevenths) {
  World world(settings());
  world.addBody(floorSlab(0.0, 100.0, material(0.0, 0.5)));
  BodyDefinition def = sphere(0.5, Vec3(0, 0.5, 0), 1.0, material(0.0, 0.5));
  def.linearVelocity = Vec3(5, 0, 0);
  const BodyId id = world.addBody(def);
  stepN(world, 60);
  const RigidBody& body = world.body(id);
  const double v = body.linearVelocity().x();
  measured("speed_mps", v);
  EXPECT_NEAR(v, 5.0 * 5.0 / 7.0, 1e-6 * 5.0);
  EXPECT_NEAR(v + body.angularVelocity().z() * 0.5, 0.0, 1e-6);
}

// The same rolling ball, the issue's check that reported velocities are the
// position change: on a flat floor it rolls with no vertical velocity, and
// its height does not change. Ours: |vy| below 1e-9 m/s and the height
// change over each step below 1e-9 m, over two seconds of rolling.
TEST(PeerFriction, RollingBallReportsNoVerticalVelocity) {
  World world(settings());
  world.addBody(floorSlab(0.0, 100.0, material(0.0, 0.5)));
  BodyDefinition def = sphere(0.5, Vec3(0, 0.5, 0), 1.0, material(0.0, 0.5));
  def.linearVelocity = Vec3(2, 0, 0);
  def.angularVelocity = Vec3(0, 0, -4);  // rolling from the start
  const BodyId id = world.addBody(def);
  stepN(world, 30);  // settle into the contact's resting depth
  double worstSpeed = 0.0, worstChange = 0.0;
  for (int i = 0; i < 120; ++i) {
    const double before = world.body(id).position().y();
    world.step();
    worstSpeed = std::max(worstSpeed, std::abs(world.body(id).linearVelocity().y()));
    worstChange = std::max(worstChange, std::abs(world.body(id).position().y() - before));
  }
  measured("worst_vertical_speed_mps", worstSpeed);
  measured("worst_height_change_m", worstChange);
  EXPECT_LT(worstSpeed, 1e-9);
  EXPECT_LT(worstChange, 1e-9);
}

}  // namespace
}  // namespace physdbg::peers
