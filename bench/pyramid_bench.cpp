// "pyramid": the 5050-box pyramid (base 100, one box deep) in physdbg and in
// Bullet, 500 steps each, sleeping on as in both engines' defaults. The
// largest displacement says whether the pyramid stood.
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/side_by_side.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::bench {
namespace {

// One row per thread count (side_by_side.h), each against the same
// single-threaded Bullet run.
void runPyramidBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int base = options.quick ? 5 : 100;
  const int steps = options.quick ? 10 : 500;
  const SceneDescription scene = pyramidScene(base);
  const EngineRun peer = runBullet(scene, steps, scene.world.allowSleep);
  std::optional<double> singleThreadMs;
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun ours = runOurs(scene, steps, options, threads);
    nlohmann::json record = benchRecord("pyramid/base" + std::to_string(base), base * (base + 1) / 2,
                                        ours.msPerStep, peer.ran ? "bullet 3.24 btDbvt+SI(10)" : "", peer.msPerStep);
    addThreadFields(record, threads, ours.msPerStep, singleThreadMs);
    addStageFields(record, ours, steps);
    if (threads == 1) singleThreadMs = ours.msPerStep;
    record["solver"] = solverKindName(options.solver.value_or(scene.world.solver.kind));
    record["steps"] = steps;
    record["sleeping"] = scene.world.allowSleep;
    record["ours_largest_displacement"] = largestDisplacement(ours);
    record["ours_final_kinetic_energy"] = ours.kineticEnergy;
    if (peer.ran) {
      record["peer_largest_displacement"] = largestDisplacement(peer);
      record["peer_final_kinetic_energy"] = peer.kineticEnergy;
    }
    sink(record);
  }
}

}  // namespace

Benchmark pyramidBenchmark() {
  return {"pyramid", "5050-box pyramid (base 100), 500 steps, against Bullet", runPyramidBenchmark};
}

}  // namespace physdbg::bench
