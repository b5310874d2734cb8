#pragma once
// Which pipeline stages and debug layers a scene actually used, read from the
// engine's counters over a run: a spheres-only scene must show no GJK/EPA
// calls, a scene with no layers requested must emit no primitives.
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace physdbg::reports {

struct StageCounters {
  std::string scene;
  int steps = 0;
  long long candidatePairs = 0, narrowPairs = 0, fastPath = 0, boxBox = 0, gjk = 0, epa = 0, reused = 0;
  long long manifolds = 0, manifoldPoints = 0, staticPairsTested = 0;
  int bodiesWithLocks = 0;
  std::string layersRequested;  // empty: none
  long long primitivesEmitted = 0;  // summed over every step's frame
};

// Runs `steps` steps of the scene and emits the requested layers after each.
// Throws std::invalid_argument for an unknown layer name.
StageCounters countStages(const SceneDescription& scene, int steps, const std::string& layers);

}  // namespace physdbg::reports
