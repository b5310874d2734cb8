#include "reports/stage_report.h"

#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"

namespace physdbg::reports {

StageCounters countStages(const SceneDescription& scene, int steps, const std::string& layers) {
  const debugdraw::LayerSet layerSet = layers.empty() ? debugdraw::LayerSet{} : debugdraw::parseLayers(layers);
  World world = buildWorld(scene);
  StageCounters counters;
  counters.scene = scene.name;
  counters.steps = steps;
  counters.layersRequested = layers;
  for (const RigidBody& body : world.bodies()) counters.bodiesWithLocks += body.hasLocks() ? 1 : 0;
  debugdraw::Frame frame;
  for (int i = 0; i < steps; ++i) {
    world.step();
    const StepStats& stats = world.lastStepStats();
    counters.candidatePairs += stats.candidatePairs;
    counters.narrowPairs += stats.narrowPhase.pairs;
    counters.fastPath += stats.narrowPhase.fastPath;
    counters.boxBox += stats.narrowPhase.boxBox;
    counters.gjk += stats.narrowPhase.gjk;
    counters.epa += stats.narrowPhase.epa;
    counters.reused += stats.narrowPhase.reused;
    counters.manifolds += stats.manifolds;
    counters.manifoldPoints += stats.manifoldPoints;
    counters.staticPairsTested += stats.staticPairsTested;
    frame.clear();
    emitDebugDraw(world, layerSet, frame);
    counters.primitivesEmitted += static_cast<long long>(frame.primitiveCount());
  }
  return counters;
}

}  // namespace physdbg::reports
