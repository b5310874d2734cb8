// Stacks and pyramids: tall, large, uneven in mass, far from the origin, and
// stepped with very large and very small time steps.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "reports/stability_cases.h"
#include "reports/stability_support.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::reports {
namespace {

double horizontalDrift(const World& world, const std::vector<Vec3>& start) {
  double largest = 0.0;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const Vec3 delta = world.bodies()[i].position() - start[i];
    largest = std::max(largest, std::hypot(delta.x(), delta.z()));
  }
  return largest;
}

// A stack of unit boxes: it must neither topple nor sink. Each resting
// contact may keep up to the solver's slop (5 mm) of overlap, so the top box
// may sink by slop per box and no more.
StabilityOutcome runStack(int count, double dt, double seconds) {
  SceneDescription scene = stackScene(count);
  scene.world.dt = dt;
  World world = buildWorld(scene);
  const auto start = positionsOf(world);
  const int steps = static_cast<int>(std::lround(seconds / dt));
  const int ran = runSteps(world, steps);
  const double drift = horizontalDrift(world, start);
  const double sink = start.back().y() - world.bodies().back().position().y();
  const double allowedSink = count * (scene.world.solver.linearSlop + 0.001);
  StabilityOutcome outcome;
  outcome.figure = drift;
  outcome.pass = ran == steps && world.numericalFaults().empty() && drift < 0.05 && std::abs(sink) < allowedSink;
  outcome.detail = format("%.0f steps; top box sank %.4f m (allowed %.3f)", ran, sink, allowedSink) + faultNote(world);
  return outcome;
}

StabilityOutcome runPyramid(int base, int steps) {
  World world = buildWorld(pyramidScene(base));
  const auto start = positionsOf(world);
  const int ran = runSteps(world, steps);
  StabilityOutcome outcome;
  outcome.figure = largestDisplacement(world, start);
  outcome.pass = ran == steps && world.numericalFaults().empty() && outcome.figure < 0.1;
  outcome.detail = format("%.0f boxes, %.0f steps", base * (base + 1) / 2.0, ran) + faultNote(world);
  return outcome;
}

// A heavy box on a light one on the floor: the light box must hold it up.
StabilityOutcome runMassRatio(double ratio, int steps) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 5.0));
  scene.bodies.push_back(dynamicBox(Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0));
  scene.bodies.push_back(dynamicBox(Vec3(0, 1.5, 0), Vec3(0.5, 0.5, 0.5), ratio));
  World world = buildWorld(scene);
  const int ran = runSteps(world, steps);
  StabilityOutcome outcome;
  outcome.figure = 1.5 - world.body(2).position().y();
  const double drift = std::hypot(world.body(2).position().x(), world.body(2).position().z());
  outcome.pass = ran == steps && world.numericalFaults().empty() && outcome.figure < 0.05 && drift < 0.01;
  outcome.detail = format("%.0f steps; heavy box drifted %.2g m sideways", ran, drift) + faultNote(world);
  return outcome;
}

// The same pyramid far away must behave as at the origin: relative positions
// (body minus pyramid origin) agree within 1 mm.
StabilityOutcome runFarPyramid(double distance, int base, int steps) {
  const Vec3 origin(distance, distance, distance);
  World near = buildWorld(pyramidScene(base));
  World far = buildWorld(pyramidScene(base, origin));
  const int ranNear = runSteps(near, steps);
  const int ranFar = runSteps(far, steps);
  double largest = 0.0;
  for (std::size_t i = 0; i < near.bodyCount(); ++i) {
    const Vec3 relative = far.bodies()[i].position() - origin;
    largest = std::max(largest, (relative - near.bodies()[i].position()).norm());
  }
  int sleepingNear = near.lastStepStats().sleepingBodies, sleepingFar = far.lastStepStats().sleepingBodies;
  StabilityOutcome outcome;
  outcome.figure = largest;
  outcome.pass = ranNear == steps && ranFar == steps && far.numericalFaults().empty() && largest < 1e-3;
  outcome.detail = format("%.0f steps; sleeping at the end: %.0f near, %.0f far", steps, sleepingNear, sleepingFar) +
                   faultNote(far);
  return outcome;
}

}  // namespace

std::vector<StabilityCase> stackingCases() {
  std::vector<StabilityCase> cases;
  cases.push_back({"tall_stack", "20 unit boxes stay upright: sideways drift < 0.05 m, top sinks < 6 mm per box",
                   "m", [](RunLength length) {
                     return runStack(20, 1.0 / 60.0, length == RunLength::Test ? 4.0 : 10.0);
                   }});
  cases.push_back({"large_pyramid", "pyramid one box deep holds: largest displacement < 0.1 m (test base 20, report base 40)",
                   "m", [](RunLength length) {
                     return length == RunLength::Test ? runPyramid(20, 300) : runPyramid(40, 600);
                   }});
  for (const double ratio : {100.0, 1000.0, 10000.0}) {
    cases.push_back({"mass_ratio_" + std::to_string(static_cast<int>(ratio)),
                     "box of mass " + std::to_string(static_cast<int>(ratio)) +
                         " rests on a box of mass 1: it sinks < 0.05 m, drifts < 0.01 m",
                     "m", [ratio](RunLength length) { return runMassRatio(ratio, length == RunLength::Test ? 120 : 600); }});
  }
  const std::pair<double, const char*> distances[] = {{1e4, "1e4"}, {1e6, "1e6"}, {1e7, "1e7"}};
  for (const auto& [distance, text] : distances) {
    cases.push_back({std::string("far_pyramid_") + text,
                     std::string("pyramid (base 10) offset by ") + text +
                         " m on every axis: relative positions within 1e-3 m of the one at the origin",
                     "m", [distance = distance](RunLength length) {  // clang 14 cannot capture a binding
                       return runFarPyramid(distance, 10, length == RunLength::Test ? 120 : 600);
                     }});
  }
  cases.push_back({"large_dt", "10-box stack stepped at dt = 1/15 s for 10 s: drift < 0.05 m, no sinking", "m",
                   [](RunLength) { return runStack(10, 1.0 / 15.0, 10.0); }});
  cases.push_back({"small_dt", "10-box stack stepped at dt = 1/10000 s: drift < 0.05 m, no sinking", "m",
                   [](RunLength length) { return runStack(10, 1.0 / 10000.0, length == RunLength::Test ? 0.2 : 2.0); }});
  return cases;
}

}  // namespace physdbg::reports
