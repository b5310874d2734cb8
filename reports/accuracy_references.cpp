#include "reports/accuracy_references.h"

#include <algorithm>
#include <cmath>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/narrowphase/narrow_phase.h"
#include "reports/stability_support.h"

namespace physdbg::reports {
namespace {

constexpr double kGravity = 9.81;

int stepsFor(double seconds, const WorldSettings& settings) {
  return static_cast<int>(std::lround(seconds / settings.dt));
}

class WorldSimulation final : public ReferenceSimulation {
 public:
  explicit WorldSimulation(const SceneDescription& scene) : world_(buildWorld(scene)) {}
  void step() override { world_.step(); }
  Vec3 position(std::size_t body) const override { return world_.body(static_cast<BodyId>(body)).position(); }
  Vec3 linearVelocity(std::size_t body) const override {
    return world_.body(static_cast<BodyId>(body)).linearVelocity();
  }

 private:
  World world_;
};

}  // namespace

std::unique_ptr<ReferenceSimulation> physdbgSimulation(const SceneDescription& scene) {
  return std::make_unique<WorldSimulation>(scene);
}

namespace {

SceneDescription sceneWith(const WorldSettings& settings, std::vector<BodyDefinition> bodies) {
  SceneDescription scene;
  scene.world = settings;
  scene.bodies = std::move(bodies);
  return scene;
}

// Exact after n steps only when n * dt == T; the sweep's dt all divide 1 s.
ReferenceResult freeFall(const WorldSettings& settings, const SimulationFactory& make) {
  const auto simulation = make(sceneWith(settings, {dynamicSphere(Vec3::Zero(), 0.5)}));
  const int steps = stepsFor(1.0, settings);
  for (int i = 0; i < steps; ++i) simulation->step();
  const double t = steps * settings.dt;
  return {std::abs(simulation->position(0).y() + 0.5 * kGravity * t * t), ""};
}

// v' = g - k v: v(t) = g/k + (v0 - g/k) e^{-kt}, x(t) = x0 + (g/k) t + (v0 - g/k)(1 - e^{-kt}) / k.
ReferenceResult projectileWithDrag(const WorldSettings& settings) {
  constexpr double k = 0.5;
  World world(settings);
  BodyDefinition ball = dynamicSphere(Vec3::Zero(), 0.5);
  ball.linearVelocity = Vec3(10, 10, 0);
  ball.linearDrag = k;
  const BodyId id = world.addBody(ball);
  const int steps = stepsFor(2.0, settings);
  for (int i = 0; i < steps; ++i) world.step();
  const double t = world.time(), decay = std::exp(-k * t);
  const Vec3 terminal = settings.gravity / k;
  const Vec3 expected = terminal * t + (ball.linearVelocity - terminal) * (1.0 - decay) / k;
  return {(world.body(id).position() - expected).norm(), ""};
}

// Dropped from h = 1 m with restitution e = 0.5: the rebound reaches e^2 h.
ReferenceResult bounce(const WorldSettings& settings, const SimulationFactory& make) {
  constexpr double e = 0.5, h = 1.0;
  BodyDefinition floor = floorAt(Vec3::Zero(), 0.0, 5.0);
  floor.material.restitution = e;
  BodyDefinition ball = dynamicSphere(Vec3(0, h + 0.5, 0), 0.5);
  ball.material.restitution = e;
  const auto simulation = make(sceneWith(settings, {floor, ball}));
  bool rising = false;
  double apex = 0.0;
  const int steps = stepsFor(1.2, settings);
  for (int i = 0; i < steps; ++i) {
    simulation->step();
    if (simulation->linearVelocity(1).y() > 0.0) rising = true;
    if (rising) apex = std::max(apex, simulation->position(1).y() - 0.5);
  }
  // Rising by under a millimetre is resting jitter, not a rebound.
  return {std::abs(apex - e * e * h), rising && apex > 1e-3 ? "" : "no rebound"};
}

// A unit box sliding at v0 = 4 m/s with mu = 0.5 stops after v0^2 / (2 mu g).
ReferenceResult slideToRest(const WorldSettings& settings, const SimulationFactory& make) {
  constexpr double mu = 0.5, v0 = 4.0;
  WorldSettings noSleep = settings;
  noSleep.allowSleep = false;
  BodyDefinition floor = floorAt(Vec3::Zero(), 0.0, 20.0);
  floor.material = {0.0, mu, mu};
  BodyDefinition box = dynamicBox(Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5));
  box.material = {0.0, mu, mu};
  box.linearVelocity = Vec3(v0, 0, 0);
  const auto simulation = make(sceneWith(noSleep, {floor, box}));
  const int steps = stepsFor(1.5, settings);
  for (int i = 0; i < steps; ++i) simulation->step();
  return {std::abs(simulation->position(1).x() - v0 * v0 / (2 * mu * kGravity)), ""};
}

using PeerMeasure = ReferenceResult (*)(const WorldSettings&, const SimulationFactory&);

// The reference run in physdbg.
std::function<ReferenceResult(const WorldSettings&)> inPhysdbg(PeerMeasure measure) {
  return [measure](const WorldSettings& settings) {
    const SimulationFactory physdbg = [](const SceneDescription& scene) { return physdbgSimulation(scene); };
    return measure(settings, physdbg);
  };
}

// Torque-free box spun near its intermediate axis: energy and angular
// momentum are constant while the spin flips. Error: the larger relative drift.
ReferenceResult tumblingBox(const WorldSettings& settings) {
  WorldSettings free = settings;
  free.gravity = Vec3::Zero();
  free.allowSleep = false;
  World world(free);
  BodyDefinition box = dynamicBox(Vec3::Zero(), Vec3(0.1, 0.2, 0.3));
  box.angularVelocity = Vec3(0.01, 5.0, 0.01);
  const BodyId id = world.addBody(box);
  const double energy = world.body(id).kineticEnergy();
  const Vec3 momentum = world.body(id).angularMomentum();
  double drift = 0.0;
  int flips = 0;
  double previousSign = 1.0;
  const int steps = stepsFor(4.0, settings);
  for (int i = 0; i < steps; ++i) {
    world.step();
    const RigidBody& body = world.body(id);
    drift = std::max({drift, std::abs(body.kineticEnergy() / energy - 1.0),
                      (body.angularMomentum() - momentum).norm() / momentum.norm()});
    const double spin = (body.orientation().conjugate() * body.angularVelocity()).y();
    if (spin * previousSign < 0.0) {
      ++flips;
      previousSign = -previousSign;
    }
  }
  return {drift, std::to_string(flips) + " flips"};
}

ReferenceResult depthError(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                           double expected, const NarrowPhaseOptions& options) {
  const ContactResult result = collide(a, ta, b, tb, options);
  return {std::abs(result.depth - expected), ""};
}

}  // namespace

std::vector<TimeStepReference> timeStepReferences() {
  return {
      {"free_fall", "y(1 s) = -g/2", inPhysdbg(freeFall), freeFall, ""},
      {"projectile_drag", "x(2 s) from v' = g - k v, k = 0.5 1/s", projectileWithDrag, {},
       "not run in the peer: its bodies get no drag (Bullet's linear damping, v *= (1 - d)^dt, is not mapped)"},
      {"bounce", "rebound = e^2 h = 0.25 m (e = 0.5, h = 1 m)", inPhysdbg(bounce), bounce, ""},
      {"slide_to_rest", "distance = v^2 / (2 mu g) = 1.631 m", inPhysdbg(slideToRest), slideToRest, ""},
      {"tumbling_box", "kinetic energy and angular momentum constant (relative drift)", tumblingBox, {},
       "not run in the peer: the comparison reads energy and angular momentum, which the peer's body view does not "
       "give"},
  };
}

std::vector<DepthReference> depthReferences() {
  const auto sphere = std::make_shared<SphereCollider>(0.5);
  const auto box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  const Transform origin{Vec3::Zero(), Quat::Identity()};
  const Transform sphereOffset{Vec3(0.3, 0.8, 0.2).normalized() * 0.9, Quat::Identity()};
  const Transform turnedAbove{Vec3(0.1, 0.9, -0.05), Quat(Eigen::AngleAxisd(0.5, Vec3::UnitY()))};
  return {
      {"depth_sphere_sphere", "depth 0.1 m (radii 0.5, centres 0.9 apart)",
       [=](const NarrowPhaseOptions& options) { return depthError(*sphere, origin, *sphere, sphereOffset, 0.1, options); }},
      {"depth_box_box", "depth 0.1 m (unit boxes, upper one turned 0.5 rad about y)",
       [=](const NarrowPhaseOptions& options) { return depthError(*box, origin, *box, turnedAbove, 0.1, options); }},
  };
}

}  // namespace physdbg::reports
