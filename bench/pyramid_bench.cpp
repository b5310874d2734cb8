// Pyramids in physdbg and in Bullet:
// - "pyramid": the 5050-box pyramid (base 100, one box deep), 500 steps,
//   sleeping on as in both engines' defaults;
// - "jolt_pyramid": Jolt's PerformanceTest pyramid (scenes/stacking_scenes.h,
//   scenes/jolt_pyramid.json: 1240 boxes of 2 m in 15 layers, sleeping off),
//   500 steps.
// The largest displacement says whether a pyramid stood, the same-work
// verdict whether both engines ended in the same state.
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/side_by_side.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::bench {
namespace {

// One row per thread count (side_by_side.h), each against the same
// single-threaded Bullet run. `bodySize`: the boxes' edge, for the verdict.
void runPyramid(const std::string& name, const SceneDescription& scene, int steps, double bodySize,
                const BenchOptions& options, const BenchSink& sink) {
  const EngineRun peer = runBullet(scene, steps, scene.world.allowSleep);
  std::optional<double> singleThreadMs;
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun ours = runOurs(scene, steps, options, threads);
    nlohmann::json record = benchRecord(name, static_cast<long long>(scene.bodies.size() - 1), ours.msPerStep,
                                        peer.ran ? "bullet 3.24 btDbvt+SI(10)" : "", peer.msPerStep);
    addThreadFields(record, threads, ours.msPerStep, singleThreadMs);
    addStageFields(record, ours, steps);
    if (threads == 1) singleThreadMs = ours.msPerStep;
    record["solver"] = solverKindName(options.solver.value_or(scene.world.solver.kind));
    record["steps"] = steps;
    record["sleeping"] = scene.world.allowSleep;
    WorkCheck check;
    check.firstDynamic = 1;  // after the floor
    check.bodySize = bodySize;
    check.outside = [](const Vec3& position) { return position.y() < -0.01; };  // through the floor
    addWorkFields(record, ours, peer, check);
    record["ours_largest_displacement"] = largestDisplacement(ours);
    record["ours_final_kinetic_energy"] = ours.kineticEnergy;
    if (peer.ran) {
      record["peer_largest_displacement"] = largestDisplacement(peer);
      record["peer_final_kinetic_energy"] = peer.kineticEnergy;
    }
    sink(record);
  }
}

void runPyramidBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int base = options.quick ? 5 : 100;
  runPyramid("pyramid/base" + std::to_string(base), pyramidScene(base), options.quick ? 10 : 500, 1.0, options,
             sink);
}

void runJoltPyramidBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const SceneDescription scene = joltPyramidScene();
  runPyramid("jolt_pyramid", scene, options.quick ? 10 : scene.steps, 2.0, options, sink);
}

}  // namespace

Benchmark pyramidBenchmark() {
  return {"pyramid", "5050-box pyramid (base 100), 500 steps, against Bullet", runPyramidBenchmark};
}

Benchmark joltPyramidBenchmark() {
  return {"jolt_pyramid",
          "Jolt's PerformanceTest pyramid (1240 boxes of 2 m, 15 layers, sleeping off), 500 steps, against Bullet",
          runJoltPyramidBenchmark};
}

}  // namespace physdbg::bench
