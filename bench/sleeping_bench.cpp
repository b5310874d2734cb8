// "sleeping": what resting props cost. 100 spheres fall onto a floor, alone
// and then beside N boxes asleep on a floor far away, in physdbg and in
// Bullet. A level full of sleeping props should cost what its moving bodies
// cost: each record carries the step time with the sleepers over the step
// time without them, for both engines, and the heap each run holds per body.
//
// Each engine takes one step before the timed ones (reported apart as
// first_step_ms): that step is the world settling in, every new proxy's
// first broad-phase query and per-body tables sized, a cost of building the
// level, not of stepping it.
//
// Same work: the sleepers never meet the spheres, so each engine's spheres
// must end where they ended alone (physdbg: bit for bit), and every sleeper
// must still be asleep where it started.
#include <cmath>
#include <memory>
#include <string>
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/side_by_side.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg::bench {
namespace {

constexpr int kFallingSpheres = 100;
constexpr double kPropSpacing = 1.5;
constexpr double kFarAway = 2000.0;  // m along x: no prop's box comes near a sphere's

BodyDefinition floorAt(const Vec3& topCentre, double halfWidth) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(Vec3(halfWidth, 0.5, halfWidth));
  body.position = topCentre - Vec3(0, 0.5, 0);
  body.isStatic = true;
  body.material = {0.2, 0.5, 0.5};
  return body;
}

// Body 0 the spheres' floor, then the spheres on a 10 x 10 grid, 1.2 m
// apart, each at its own height (2 to 4 m) so they land at different steps;
// then, with props, the far floor and the props on a square grid.
SceneDescription sleepingScene(int props) {
  SceneDescription scene;
  scene.name = props > 0 ? "sleeping_props" : "falling_spheres";
  scene.world.allowSleep = true;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 8.0));
  const auto sphere = std::make_shared<SphereCollider>(0.5);
  for (int i = 0; i < kFallingSpheres; ++i) {
    BodyDefinition body;
    body.collider = sphere;
    body.position = Vec3((i % 10 - 4.5) * 1.2, 2.0 + 0.2 * (i * 7 % 11), (i / 10 - 4.5) * 1.2);
    body.material = {0.2, 0.5, 0.5};
    scene.bodies.push_back(body);
  }
  if (props == 0) return scene;
  const int side = static_cast<int>(std::ceil(std::sqrt(props)));
  scene.bodies.push_back(floorAt(Vec3(kFarAway, 0, 0), 0.5 * side * kPropSpacing + 1.0));
  const auto box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  for (int i = 0; i < props; ++i) {
    BodyDefinition body;
    body.collider = box;
    body.position = Vec3(kFarAway + (i % side - 0.5 * (side - 1)) * kPropSpacing, 0.5,
                         (i / side - 0.5 * (side - 1)) * kPropSpacing);
    body.material = {0.2, 0.5, 0.5};
    scene.sleeping.push_back(static_cast<BodyId>(scene.bodies.size()));
    scene.bodies.push_back(body);
  }
  return scene;
}

// Largest distance between where a sphere ended alone and with the props.
double sphereMismatch(const EngineRun& alone, const EngineRun& beside) {
  double largest = 0.0;
  for (int i = 1; i <= kFallingSpheres; ++i)
    largest = std::max(largest, (alone.finalPositions[i] - beside.finalPositions[i]).norm());
  return largest;
}

double largestPropMove(const EngineRun& run) {
  double largest = 0.0;
  for (std::size_t i = kFallingSpheres + 2; i < run.finalPositions.size(); ++i)
    largest = std::max(largest, (run.finalPositions[i] - run.startPositions[i]).norm());
  return largest;
}

void runSleepingBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int props = options.quick ? 1000 : 99899;
  const int steps = options.quick ? 10 : 120;
  const SceneDescription alone = sleepingScene(0), beside = sleepingScene(props);
  const EngineRun peerAlone = runBullet(alone, steps, true, true);
  const EngineRun peer = runBullet(beside, steps, true, true);
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun oursAlone = runOurs(alone, steps, options, threads, true);
    const EngineRun ours = runOurs(beside, steps, options, threads, true);
    nlohmann::json record = benchRecord("sleeping/props", props, ours.msPerStep,
                                        peer.ran ? "bullet 3.24 btDbvt+SI(10)" : "", peer.msPerStep);
    record["threads"] = threads;
    record["steps"] = steps;
    addStageFields(record, ours, steps);
    // One engine's fields; true when its spheres and props ended within `tolerance` of the same work.
    const auto engineFields = [&](const std::string& prefix, const EngineRun& alone, const EngineRun& run,
                                  double tolerance) {
      record[prefix + "_first_step_ms"] = run.firstStepMs;
      record[prefix + "_alone_ms"] = alone.msPerStep;
      record[prefix + "_over_alone"] = run.msPerStep / alone.msPerStep;
      record[prefix + "_bytes_per_body"] = run.heapBytes / static_cast<double>(beside.bodies.size());
      record[prefix + "_sphere_mismatch"] = sphereMismatch(alone, run);
      record[prefix + "_largest_prop_move"] = largestPropMove(run);
      return sphereMismatch(alone, run) <= tolerance && largestPropMove(run) <= tolerance;
    };
    bool sameWork = engineFields("ours", oursAlone, ours, 0.0);  // bit for bit
    if (peer.ran) sameWork = engineFields("peer", peerAlone, peer, 1e-4) && sameWork;
    record["same_work"] = sameWork;
    sink(record);
  }
}

}  // namespace

Benchmark sleepingBenchmark() {
  return {"sleeping",
          "100 falling spheres alone and beside 99,899 boxes asleep far away, 120 steps after a first, against "
          "Bullet: the cost of sleepers",
          runSleepingBenchmark};
}

}  // namespace physdbg::bench
