#pragma once
// Helpers shared by the peer cases (tests/peers/): bodies and worlds set up the
// way the peers' tests set theirs up, the closed forms of the engine's
// integrator (semi-implicit Euler per substep, motion.h), a contact listener
// that records events with their step, a bit-level state hash, and
// `measured`, which prints each case's figure and records it in the XML
// report (--gtest_output=xml) so the table in tests/README.md can be checked.
//
// Every case names the peer file and test it comes from, the peer's
// tolerance, ours and why. "Peer-specific" expectations (a peer's slop, its
// linear cast, its integration order) are replaced by the engine-neutral
// analytic answer, and the case says so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"
#include "scenes/body_builders.h"
#include "scenes/scene.h"

namespace physdbg::peers {

constexpr double kGravity = 9.81;  // m/s^2, the peers' 9.81 (Box2D's 10 is said where used)

// ----------------------------------------------------------------- figures

// Prints "[ peer     ] Suite.Test: what = value" and records it as a test
// property, so every case's measured figure is in the log and in the XML.
inline void measured(const std::string& what, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  ::testing::Test::RecordProperty(what, text);
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::printf("[ peer     ] %s.%s: %s = %s\n", info ? info->test_suite_name() : "?", info ? info->name() : "?",
              what.c_str(), text);
}

// ----------------------------------------------------------------- bodies

inline Material material(double restitution, double friction) {
  Material m;
  m.restitution = restitution;
  m.staticFriction = friction;
  m.dynamicFriction = friction;
  return m;
}

// A static slab whose top face is the plane y = top (Jolt's CreateFloor: 200 m
// wide, 1 m below its top; Box2D's ground box).
inline BodyDefinition floorSlab(double top = 0.0, double halfWidth = 100.0, const Material& m = material(0.0, 0.6)) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(Vec3(halfWidth, 1.0, halfWidth));
  body.position = Vec3(0.0, top - 1.0, 0.0);
  body.isStatic = true;
  body.material = m;
  return body;
}

inline BodyDefinition sphere(double radius, const Vec3& position, double mass = 1.0,
                             const Material& m = material(0.0, 0.6)) {
  BodyDefinition body = dynamicBody(std::make_shared<SphereCollider>(radius), position, mass);
  body.material = m;
  return body;
}

inline BodyDefinition box(const Vec3& halfExtents, const Vec3& position, double mass = 1.0,
                          const Material& m = material(0.0, 0.6)) {
  BodyDefinition body = dynamicBody(std::make_shared<BoxCollider>(halfExtents), position, mass);
  body.material = m;
  return body;
}

// ----------------------------------------------------------------- worlds

// The engine's defaults (sequential impulses, 8 substeps), sleeping as asked.
inline WorldSettings settings(double dt = 1.0 / 60.0, bool allowSleep = false) {
  WorldSettings s;
  s.dt = dt;
  s.allowSleep = allowSleep;
  return s;
}

// Jolt's ZeroGravity(), Box2D's MakeWorld(0).
inline WorldSettings weightless(double dt = 1.0 / 60.0) {
  WorldSettings s = settings(dt);
  s.gravity = Vec3::Zero();
  return s;
}

// The substep a free body (in no manifold) and a body in flight take: the
// step cut into solver.substeps (sequential_impulse_solver.cpp).
// The substeps of a body in flight and their length (solver_settings.h:
// more than `substeps` at long steps, where a 60 Hz contact needs them).
inline int flightSubsteps(const WorldSettings& s) { return flightSubstepCount(s.solver, s.dt); }
inline double substep(const WorldSettings& s) { return s.dt / flightSubsteps(s); }

inline void stepN(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

// A scene written as JSON and loaded with the scenes library, as the
// physdbg command would (scenes/README.md).
inline World sceneWorld(const std::string& json, const std::string& name = "peer.json") {
  return buildWorld(parseScene(json, name));
}

// ----------------------------------------------------------------- closed forms

// N semi-implicit Euler steps of length h under constant acceleration a
// (v += a h, then x += v h): x_N = x0 + v0 N h + a h^2 N (N + 1) / 2.
inline double eulerPosition(double x0, double v0, double a, double h, long n) {
  const double count = static_cast<double>(n);
  return x0 + v0 * count * h + a * h * h * count * (count + 1.0) / 2.0;
}

// What semi-implicit Euler keeps exactly in free flight under a pull g
// (v += -g h; y += v h): E = v^2/2 + g y - g h v/2 (per unit mass; v up,
// y the height). Box2D v3's test_restitution.c MeasureEnergy uses the same
// half-substep phase term; engine/solver/bounce.h derives it.
inline double flightEnergy(double height, double upwardVelocity, double g, double h) {
  return 0.5 * upwardVelocity * upwardVelocity + g * height - 0.5 * g * h * upwardVelocity;
}

// Angle between two orientations (q and -q are the same rotation).
inline double angleBetween(const Quat& a, const Quat& b) { return a.angularDistance(b); }

// ----------------------------------------------------------------- events

struct RecordedEvent {
  enum Kind { Begin, Stay, End } kind;
  std::uint32_t a, b;
  int step;  // 1-based: the step that fired it
  Vec3 normal = Vec3::Zero();
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
};

class RecordingListener final : public ContactListener {
 public:
  explicit RecordingListener(World& world) : world_(world) { world.setContactListener(this); }
  ~RecordingListener() override { world_.setContactListener(nullptr); }
  RecordingListener(const RecordingListener&) = delete;
  RecordingListener& operator=(const RecordingListener&) = delete;

  void onContactBegin(const Contact& contact) override { record(RecordedEvent::Begin, contact.a, contact.b, &contact); }
  void onContactStay(const Contact& contact) override { record(RecordedEvent::Stay, contact.a, contact.b, &contact); }
  void onContactEnd(std::uint32_t a, std::uint32_t b) override { record(RecordedEvent::End, a, b, nullptr); }

  int count(RecordedEvent::Kind kind) const {
    int n = 0;
    for (const RecordedEvent& event : events) n += event.kind == kind;
    return n;
  }
  int count(RecordedEvent::Kind kind, std::uint32_t a, std::uint32_t b) const {
    int n = 0;
    for (const RecordedEvent& event : events) n += event.kind == kind && event.a == a && event.b == b;
    return n;
  }
  void clear() { events.clear(); }

  std::vector<RecordedEvent> events;

 private:
  void record(RecordedEvent::Kind kind, std::uint32_t a, std::uint32_t b, const Contact* contact) {
    RecordedEvent event{kind, a, b, world_.stepCount() + 1};
    if (contact != nullptr) {
      event.normal = contact->result.normal;
      event.pointA = contact->result.pointA;
      event.pointB = contact->result.pointB;
    }
    events.push_back(event);
  }
  World& world_;
};

// ----------------------------------------------------------------- state hash

// FNV-1a over every body's position, orientation and velocities, bit for bit
// (what `physdbg simulate --hash` prints), plus sleep flags: Box2D's
// b2World_GetStateHash, Jolt's determinism comparison.
inline std::uint64_t stateHash(const World& world) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&hash](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= bytes[i];
      hash *= 1099511628211ull;
    }
  };
  for (BodyId id = 0; id < world.bodyCount(); ++id) {
    const RigidBody& body = world.body(id);
    add(body.position().data(), 3 * sizeof(double));
    add(body.orientation().coeffs().data(), 4 * sizeof(double));
    add(body.linearVelocity().data(), 3 * sizeof(double));
    add(body.angularVelocity().data(), 3 * sizeof(double));
    const unsigned char asleep = world.isAsleep(id) ? 1 : 0;
    add(&asleep, 1);
  }
  return hash;
}

}  // namespace physdbg::peers
