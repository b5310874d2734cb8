// "drop": N spheres, then N boxes, dropped into an open container, physdbg
// and Bullet on the same scene in the same run. Speed only counts with an
// intact pile, so each record also carries the final kinetic energy and how
// many bodies left the container, for both engines.
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/drop_scene.h"
#include "bench/side_by_side.h"

namespace physdbg::bench {
namespace {

int countEscaped(const EngineRun& run, const DropScene& drop) {
  int escaped = 0;
  for (std::size_t i = drop.firstDropped; i < run.finalPositions.size(); ++i) {
    if (leftContainer(run.finalPositions[i], drop.container)) ++escaped;
  }
  return escaped;
}

// One row per thread count (side_by_side.h), each against the same
// single-threaded Bullet run.
void runDrop(int count, DropShape shape, int steps, const BenchOptions& options, const BenchSink& sink) {
  const DropScene drop = dropScene(count, shape);
  const EngineRun peer = runBullet(drop.scene, steps, false);
  std::optional<double> singleThreadMs;
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun ours = runOurs(drop.scene, steps, options, threads);
    nlohmann::json record = benchRecord(std::string("drop/") + (shape == DropShape::Sphere ? "spheres" : "boxes"),
                                        count, ours.msPerStep, peer.ran ? "bullet 3.24 btDbvt+SI(10)" : "",
                                        peer.msPerStep);
    addThreadFields(record, threads, ours.msPerStep, singleThreadMs);
    addStageFields(record, ours, steps);
    if (threads == 1) singleThreadMs = ours.msPerStep;
    record["solver"] = solverKindName(options.solver.value_or(drop.scene.world.solver.kind));
    record["steps"] = steps;
    record["dt"] = drop.scene.world.dt;
    record["sleeping"] = false;
    record["ours_final_kinetic_energy"] = ours.kineticEnergy;
    record["ours_left_container"] = countEscaped(ours, drop);
    if (peer.ran) {
      record["peer_final_kinetic_energy"] = peer.kineticEnergy;
      record["peer_left_container"] = countEscaped(peer, drop);
    }
    sink(record);
  }
}

void runDropBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const std::vector<int> counts = options.quick ? std::vector<int>{64} : std::vector<int>{1000, 4000, 16000};
  const int steps = options.quick ? 10 : 600;
  for (const int count : counts) {
    for (const DropShape shape : {DropShape::Sphere, DropShape::Box}) runDrop(count, shape, steps, options, sink);
  }
}

}  // namespace

Benchmark dropBenchmark() {
  return {"drop", "N spheres and N boxes dropped into a container, 600 steps, against Bullet (N = 1000, 4000, 16000)",
          runDropBenchmark};
}

}  // namespace physdbg::bench
