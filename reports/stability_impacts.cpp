// Violent starts: deep initial overlap, very fast bodies, a perfectly elastic
// bounce and a fast spin. Each must end finite and gain no energy.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reports/stability_cases.h"
#include "reports/stability_support.h"

namespace physdbg::reports {
namespace {

// Two unit boxes on the floor, the upper one sunk 25% into the lower. The
// overlap must be undone calmly: no body ever faster than 3 m/s (the solver's
// push-out limit) and overlap below 1 cm after 2 s.
StabilityOutcome runOverlapRecovery(int steps) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 5.0));
  scene.bodies.push_back(dynamicBox(Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5)));
  scene.bodies.push_back(dynamicBox(Vec3(0, 1.25, 0), Vec3(0.5, 0.5, 0.5)));
  World world = buildWorld(scene);
  double peakSpeed = 0.0;
  int ran = 0;
  for (; ran < steps && world.numericalFaults().empty(); ++ran) {
    world.step();
    peakSpeed = std::max(peakSpeed, largestSpeed(world));
  }
  const double overlap = world.lastStepStats().largestPenetration;
  StabilityOutcome outcome;
  outcome.figure = peakSpeed;
  outcome.pass = world.numericalFaults().empty() && peakSpeed < 3.0 && overlap < 0.01;
  outcome.detail = format("%.0f steps; overlap at the end %.4f m", ran, overlap) + faultNote(world);
  return outcome;
}

// A 0.1 m sphere at 200 m/s against a static wall 0.1 m thick (no gravity):
// it must stop at the near face, never reach the far side.
StabilityOutcome runBulletIntoWall() {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  world.addBody(staticBox(Vec3::Zero(), Vec3(0.05, 2.0, 2.0)));
  BodyDefinition bullet = dynamicSphere(Vec3(-5.0, 0, 0), 0.1);
  bullet.linearVelocity = Vec3(200.0, 0, 0);
  const BodyId id = world.addBody(bullet);
  double deepest = -1e9;  // how far the sphere's front got past the near face
  for (int i = 0; i < 60 && world.numericalFaults().empty(); ++i) {
    world.step();
    deepest = std::max(deepest, world.body(id).position().x() + 0.1 + 0.05);
  }
  StabilityOutcome outcome;
  outcome.figure = deepest;
  outcome.pass = world.numericalFaults().empty() && deepest < 0.02;
  outcome.detail = format("sphere ends at x = %.4f m, speed %.3g m/s", world.body(id).position().x(),
                          world.body(id).linearVelocity().norm()) +
                   faultNote(world);
  return outcome;
}

// A 0.25 m sphere at 500 m/s into the second box of a 5-box stack. It must
// hit (the struck box moves), nothing may fall through the floor and nothing
// may stay buried in another body.
StabilityOutcome runBulletIntoStack(int steps) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 50.0));
  for (int i = 0; i < 5; ++i) scene.bodies.push_back(dynamicBox(Vec3(0, 0.5 + i, 0), Vec3(0.5, 0.5, 0.5)));
  BodyDefinition bullet = dynamicSphere(Vec3(-10.0, 1.5, 0), 0.25);
  bullet.linearVelocity = Vec3(500.0, 0, 0);
  scene.bodies.push_back(bullet);
  World world = buildWorld(scene);
  const int ran = runSteps(world, steps);
  double lowest = 1e9;
  for (const RigidBody& body : world.bodies()) {
    // Bodies knocked past the floor's edge fall freely: only those above it count.
    const bool aboveFloor = std::abs(body.position().x()) < 50.0 && std::abs(body.position().z()) < 50.0;
    if (!body.isStatic() && aboveFloor) lowest = std::min(lowest, body.collider().worldBounds(body.transform()).min.y());
  }
  const double struckMoved = (world.body(2).position() - Vec3(0, 1.5, 0)).norm();
  StabilityOutcome outcome;
  outcome.figure = world.lastStepStats().largestPenetration;
  outcome.pass = ran == steps && world.numericalFaults().empty() && outcome.figure < 0.05 && lowest > -0.05 &&
                 struckMoved > 1.0;
  outcome.detail = format("%.0f steps; struck box moved %.3g m; lowest point y = %.4f m", ran, struckMoved, lowest) +
                   faultNote(world);
  return outcome;
}

// A unit sphere with restitution 1 dropped 2 m onto a restitution-1 floor:
// no rebound may rise above the drop height (1 mm allowed).
StabilityOutcome runElasticBounce(int steps) {
  SceneDescription scene;
  BodyDefinition floor = floorAt(Vec3::Zero(), 0.0, 5.0);
  floor.material.restitution = 1.0;
  scene.bodies.push_back(floor);
  BodyDefinition ball = dynamicSphere(Vec3(0, 2.5, 0), 0.5);
  ball.material.restitution = 1.0;
  scene.bodies.push_back(ball);
  World world = buildWorld(scene);
  bool bounced = false;
  double highest = 0.0;  // of the centre after the first bounce
  int ran = 0;
  for (; ran < steps && world.numericalFaults().empty(); ++ran) {
    world.step();
    const RigidBody& body = world.body(1);
    if (body.linearVelocity().y() > 0.0) bounced = true;
    if (bounced) highest = std::max(highest, body.position().y());
  }
  StabilityOutcome outcome;
  outcome.figure = highest - 2.5;
  outcome.pass = world.numericalFaults().empty() && bounced && outcome.figure <= 1e-3;
  outcome.detail = format("%.0f steps; highest rebound %.4f of the drop", ran, (highest - 0.5) / 2.0) +
                   faultNote(world);
  return outcome;
}

// A free box (half sizes 0.1, 0.2, 0.3) spun at 100 rad/s about a
// non-principal axis: kinetic energy may fall (implicit gyroscopic terms
// damp) but never rise by more than 1e-6 relative.
StabilityOutcome runFastSpin(int steps) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.allowSleep = false;
  World world(settings);
  BodyDefinition box = dynamicBox(Vec3::Zero(), Vec3(0.1, 0.2, 0.3));
  box.angularVelocity = Vec3(1, 2, 3).normalized() * 100.0;
  const BodyId id = world.addBody(box);
  const double initialEnergy = world.body(id).kineticEnergy();
  const Vec3 initialMomentum = world.body(id).angularMomentum();
  double highest = 1.0;
  int ran = 0;
  for (; ran < steps && world.numericalFaults().empty(); ++ran) {
    world.step();
    highest = std::max(highest, world.body(id).kineticEnergy() / initialEnergy);
  }
  const double momentumDrift = (world.body(id).angularMomentum() - initialMomentum).norm() / initialMomentum.norm();
  StabilityOutcome outcome;
  outcome.figure = highest - 1.0;
  outcome.pass = world.numericalFaults().empty() && outcome.figure <= 1e-6;
  outcome.detail = format("%.0f steps; energy at the end %.6f of the start; angular momentum drift %.2g", ran,
                          world.body(id).kineticEnergy() / initialEnergy, momentumDrift) +
                   faultNote(world);
  return outcome;
}

}  // namespace

std::vector<StabilityCase> impactCases() {
  return {
      {"overlap_recovery", "box sunk 25% into another: peak speed < 3 m/s, overlap < 0.01 m after the run", "m/s",
       [](RunLength length) { return runOverlapRecovery(length == RunLength::Test ? 120 : 300); }},
      {"bullet_200_thin_wall", "0.1 m sphere at 200 m/s into a 0.1 m wall: front gets < 0.02 m past the near face",
       "m", [](RunLength) { return runBulletIntoWall(); }},
      {"bullet_500_stack", "sphere at 500 m/s into a 5-box stack: hits it, nothing below the floor, overlap < 0.05 m",
       "m", [](RunLength length) { return runBulletIntoStack(length == RunLength::Test ? 120 : 600); }},
      {"elastic_bounce", "restitution 1 sphere dropped 2 m: rebound centre never > 1e-3 m above the drop height", "m",
       [](RunLength length) { return runElasticBounce(length == RunLength::Test ? 300 : 1200); }},
      {"fast_spin", "free box spun at 100 rad/s: kinetic energy never rises by > 1e-6 relative", "relative",
       [](RunLength length) { return runFastSpin(length == RunLength::Test ? 300 : 1200); }},
  };
}

}  // namespace physdbg::reports
