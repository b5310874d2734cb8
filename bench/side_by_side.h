#pragma once
// Runs one scene in physdbg and in Bullet for the same number of steps and
// keeps what the scene benchmarks compare: time per step, final kinetic
// energy and final positions (in scene body order).
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <vector>

#include "bench/bench.h"
#include "engine/step_profile.h"
#include "scenes/scene.h"

namespace physdbg::bench {

struct EngineRun {
  bool ran = false;  // false when the engine is not built in
  double msPerStep = 0.0;
  double kineticEnergy = 0.0;
  std::vector<Vec3> startPositions, finalPositions;
  StepProfile profile;  // physdbg: summed over the steps
  // Heap in use after the last step less before the world was built
  // (glibc's mallinfo2: bytes allocated, not pages touched), so runs in one
  // process do not hide behind memory an earlier run freed.
  double heapBytes = 0.0;
  double firstStepMs = 0.0;  // with warm-up: the step taken before the timed ones
  int contacts = 0;          // touching pairs after the last step, asleep ones included
};

// Whether two runs of one scene did the same work: each engine's final
// touching pairs, mean height of the dynamic bodies and bodies outside (as
// `outside` says), and the verdict: contact counts within 20% of the larger,
// mean heights within 5% of the body size, nobody outside. A benchmark whose
// engines ended in different states (one pile balanced, the other toppled)
// compares different work, and its ratio says nothing.
struct WorkCheck {
  std::size_t firstDynamic = 0;  // scene body index of the first dynamic body
  double bodySize = 1.0;         // m
  std::function<bool(const Vec3&)> outside;
};
// Adds ours_/peer_ contacts, mean_height, outside and same_work (null
// without a peer) to `record`.
void addWorkFields(nlohmann::json& record, const EngineRun& ours, const EngineRun& peer, const WorkCheck& check);

// With options.solver, physdbg runs the scene under that solver, on
// `threads` threads (0 every core).
// With `warmUp`, one step is taken and timed apart (firstStepMs) before the
// `steps` timed ones: where the first step is the world settling in (every
// proxy's first query, per-body tables sized) and the benchmark asks what a
// step costs after it.
EngineRun runOurs(SceneDescription scene, int steps, const BenchOptions& options, int threads, bool warmUp = false);
EngineRun runBullet(const SceneDescription& scene, int steps, bool allowSleep, bool warmUp = false);

// The thread counts a scene benchmark runs physdbg on: options.threads alone
// when given (0 read as every core), else 1 and every core (just 1 on a
// one-core machine). Bullet runs once, single-threaded, as it is built.
std::vector<int> benchThreadCounts(const BenchOptions& options);

// physdbg's mean ms per step in each stage of World::step (step_profile.h),
// as record["ours_stage_ms"]: which stages bound a scene, and, set beside the
// other thread counts' rows, which gain from threads.
void addStageFields(nlohmann::json& record, const EngineRun& ours, int steps);

// Sets the record's "threads" and, after the single-thread run, "scaling":
// that run's time over this one's (2 = twice as fast on `threads` threads);
// on more than one thread also "host_scaling" (host_scaling.h), measured
// right after the run, so a low "scaling" can be told from a busy host.
void addThreadFields(nlohmann::json& record, int threads, double msPerStep, std::optional<double> singleThreadMs);

// Largest distance a body moved between the start and the end.
double largestDisplacement(const EngineRun& run);

}  // namespace physdbg::bench
