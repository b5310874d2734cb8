// "drop": N spheres, then N boxes, dropped into an open container, physdbg
// and Bullet on the same scene in the same run, each body's start jittered
// sideways (drop_scene.h). Speed only counts with an intact pile and the
// same work, so each record also carries the final kinetic energy, how many
// bodies left the container, and the same_work verdict (side_by_side.h).
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
void runDrop(int count, DropShape shape, bool jittered, int steps, const BenchOptions& options,
             const BenchSink& sink) {
  const DropScene drop = dropScene(count, shape, jittered);
  WorkCheck check;
  check.firstDynamic = static_cast<std::size_t>(drop.firstDropped);
  check.bodySize = 1.0;
  check.outside = [&drop](const Vec3& position) { return leftContainer(position, drop.container); };
  const EngineRun peer = runBullet(drop.scene, steps, false);
  std::optional<double> singleThreadMs;
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun ours = runOurs(drop.scene, steps, options, threads);
    const std::string name =
        std::string("drop/") + (shape == DropShape::Sphere ? "spheres" : "boxes") + (jittered ? "" : "_columns");
    nlohmann::json record =
        benchRecord(name, count, ours.msPerStep, peer.ran ? "bullet 3.24 btDbvt+SI(10)" : "", peer.msPerStep);
    addThreadFields(record, threads, ours.msPerStep, singleThreadMs);
    addStageFields(record, ours, steps);
    if (threads == 1) singleThreadMs = ours.msPerStep;
    record["solver"] = solverKindName(options.solver.value_or(drop.scene.world.solver.kind));
    record["steps"] = steps;
    record["dt"] = drop.scene.world.dt;
    record["sleeping"] = false;
    record["jittered"] = jittered;
    record["ours_final_kinetic_energy"] = ours.kineticEnergy;
    record["ours_left_container"] = countEscaped(ours, drop);
    if (peer.ran) {
      record["peer_final_kinetic_energy"] = peer.kineticEnergy;
      record["peer_left_container"] = countEscaped(peer, drop);
    }
    addWorkFields(record, ours, peer, check);
    sink(record);
  }
}

void runDropBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const std::vector<int> counts = options.quick ? std::vector<int>{64} : std::vector<int>{1000, 4000, 16000};
  const int steps = options.quick ? 10 : 600;
  for (const int count : counts) {
    for (const DropShape shape : {DropShape::Sphere, DropShape::Box}) runDrop(count, shape, true, steps, options, sink);
  }
  // The unjittered spheres, kept as a named extra case (drop/spheres_columns)
  // at the smallest count: double precision keeps their columns balanced,
  // Bullet's topple, and same_work says so.
  runDrop(counts.front(), DropShape::Sphere, false, steps, options, sink);
}

}  // namespace

Benchmark dropBenchmark() {
  return {"drop",
          "N spheres and N boxes dropped into a container, jittered, 600 steps, against Bullet (N = 1000, 4000, "
          "16000), and the unjittered spheres at 1000 (drop/spheres_columns)",
          runDropBenchmark};
}

}  // namespace physdbg::bench
