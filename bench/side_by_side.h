#pragma once
// Runs one scene in physdbg and in Bullet for the same number of steps and
// keeps what the scene benchmarks compare: time per step, final kinetic
// energy and final positions (in scene body order).
#include <vector>

#include "bench/bench.h"
#include "scenes/scene.h"

namespace physdbg::bench {

struct EngineRun {
  bool ran = false;  // false when the engine is not built in
  double msPerStep = 0.0;
  double kineticEnergy = 0.0;
  std::vector<Vec3> startPositions, finalPositions;
};

// With options.solver, physdbg runs the scene under that solver.
EngineRun runOurs(SceneDescription scene, int steps, const BenchOptions& options);
EngineRun runBullet(const SceneDescription& scene, int steps, bool allowSleep);

// Largest distance a body moved between the start and the end.
double largestDisplacement(const EngineRun& run);

}  // namespace physdbg::bench
