// Kinematic bodies: driven along a path by their velocities alone, and what
// they do to, and report with, static, kinematic and dynamic bodies they
// overlap. Cases from Jolt's UnitTests/Physics/PhysicsTests.cpp
// (TestPhysicsMoveKinematic) and ContactListenerTests.cpp
// (TestCollideKinematicVsNonDynamic).
#include <cmath>
#include <cstdint>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

// A small fixed generator (Jolt's UnitTestRandom is a fixed-seed mt19937):
// the same targets on every platform.
class Lcg {
 public:
  double uniform(double low, double high) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return low + (high - low) * static_cast<double>(state_ >> 11) * 0x1.0p-53;
  }
  Quat rotation() {
    const Eigen::Vector4d v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    return Quat(v[0], v[1], v[2], v[3]).normalized();
  }

 private:
  std::uint64_t state_ = 0x5eed;
};

// Jolt PhysicsTests.cpp::TestPhysicsMoveKinematic: a kinematic box is sent to
// 10 random poses (positions within 5 m, any rotation), each over 60 steps,
// at 1, 2 and 4 steps per 1/60 s (Jolt's MoveKinematic sets the velocities
// that reach the pose in that time; here they are set directly). Jolt: every
// intermediate position on the straight line within 1e-4 m and rotation on
// the slerp within 1e-5; arrival within the same. Ours: 1e-11 m and 1e-11
// rad (a constant spin turns the body about a fixed axis exactly, so the
// path is the slerp up to rounding).
TEST(PeerKinematic, MoveKinematicFollowsTheLineAndTheSlerpToItsTarget) {
  const int steps = 60;
  double worstPosition = 0.0, worstRotation = 0.0;
  for (const double dt : {1.0 / 60.0, 2.0 / 60.0, 4.0 / 60.0}) {
    World world(settings(dt));
    BodyDefinition def = box(Vec3::Ones(), Vec3::Zero());
    def.isKinematic = true;
    const BodyId id = world.addBody(def);
    Lcg random;
    for (int target = 0; target < 10; ++target) {
      RigidBody& body = world.body(id);
      const Vec3 fromPosition = body.position();
      const Quat fromRotation = body.orientation();
      const Vec3 toPosition(random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5));
      const Quat toRotation = random.rotation();
      Quat delta = toRotation * fromRotation.conjugate();
      if (delta.w() < 0.0) delta.coeffs() = -delta.coeffs();
      const Eigen::AngleAxisd turn(delta);
      body.setLinearVelocity((toPosition - fromPosition) / (steps * dt));
      body.setAngularVelocity(turn.axis() * turn.angle() / (steps * dt));
      for (int j = 1; j <= steps; ++j) {
        world.step();
        const double fraction = static_cast<double>(j) / steps;
        const Vec3 expectedPosition = fromPosition + (toPosition - fromPosition) * fraction;
        const Quat expectedRotation = fromRotation.slerp(fraction, toRotation);
        const double positionError = (world.body(id).position() - expectedPosition).norm();
        const double rotationError = angleBetween(world.body(id).orientation(), expectedRotation);
        ASSERT_LT(positionError, 1e-11) << "dt " << dt << " target " << target << " step " << j;
        ASSERT_LT(rotationError, 1e-11) << "dt " << dt << " target " << target << " step " << j;
        worstPosition = std::max(worstPosition, positionError);
        worstRotation = std::max(worstRotation, rotationError);
      }
    }
  }
  measured("worst_position_error_m", worstPosition);
  measured("worst_rotation_error_rad", worstRotation);
}

enum class Motion { Static, Kinematic, Dynamic };

const char* name(Motion motion) {
  return motion == Motion::Static ? "static" : motion == Motion::Kinematic ? "kinematic" : "dynamic";
}

// Jolt ContactListenerTests.cpp::TestCollideKinematicVsNonDynamic: two
// radius-1 spheres overlapping by 1 m, every pairing of static, kinematic and
// dynamic, each moving (active: 1 m/s towards the other) or still (a
// dynamic one asleep), no gravity, one step. Jolt, with its default (no
// kinematic-vs-non-dynamic collision): a contact is reported exactly when
// one body is dynamic; only dynamic bodies change velocity, and they are
// awake after the step; the others keep theirs exactly (==). Ours: the same,
// exactly (one begin or none; velocities bit for bit).
TEST(PeerKinematic, OnlyDynamicBodiesRespondAndOnlyTheirPairsAreReported) {
  int cases = 0;
  for (const Motion m1 : {Motion::Static, Motion::Kinematic, Motion::Dynamic})
    for (const bool active1 : {false, true})
      for (const Motion m2 : {Motion::Static, Motion::Kinematic, Motion::Dynamic})
        for (const bool active2 : {false, true}) {
          if (!((m1 != Motion::Static && active1) || (m2 != Motion::Static && active2))) continue;
          if ((m1 == Motion::Static && active1) || (m2 == Motion::Static && active2)) continue;
          SCOPED_TRACE(std::string(name(m1)) + (active1 ? " moving" : " still") + " vs " + name(m2) +
                       (active2 ? " moving" : " still"));
          ++cases;
          WorldSettings s = weightless();
          s.allowSleep = true;
          World world(s);
          const auto make = [&](Motion motion, bool active, double x, double speed) {
            BodyDefinition def = sphere(1.0, Vec3(x, 0, 0));
            def.isStatic = motion == Motion::Static;
            def.isKinematic = motion == Motion::Kinematic;
            if (motion != Motion::Static && active) def.linearVelocity = Vec3(speed, 0, 0);
            const BodyId id = world.addBody(def);
            if (motion == Motion::Dynamic && !active) world.sleep(id);
            return id;
          };
          const BodyId a = make(m1, active1, -0.5, 1.0);
          const BodyId b = make(m2, active2, 0.5, -1.0);
          const Vec3 before[] = {world.body(a).linearVelocity(), world.body(b).linearVelocity()};
          RecordingListener events(world);
          world.step();
          const bool anyDynamic = m1 == Motion::Dynamic || m2 == Motion::Dynamic;
          EXPECT_EQ(events.count(RecordedEvent::Begin, a, b), anyDynamic ? 1 : 0);
          EXPECT_EQ(events.events.size(), anyDynamic ? 1u : 0u);
          const Motion motions[] = {m1, m2};
          const BodyId ids[] = {a, b};
          for (int i = 0; i < 2; ++i) {
            if (motions[i] == Motion::Dynamic) {
              EXPECT_NE(world.body(ids[i]).linearVelocity(), before[i]) << "body " << i;
              EXPECT_FALSE(world.isAsleep(ids[i])) << "body " << i;
            } else {
              EXPECT_EQ(world.body(ids[i]).linearVelocity(), before[i]) << "body " << i;
            }
          }
        }
  measured("pairings", cases);
}

}  // namespace
}  // namespace physdbg::peers
