#include "viewer/scene_overlay.h"

#include <cstdio>
#include <string>

#include "engine/world.h"

namespace physdbg::viewer {

void addOverlay(const SceneDescription& scene, const World& world, const OverlayCounters& counters,
                debugdraw::Frame& out) {
  char line[256];
  const std::string progress =
      counters.frame && counters.frames
          ? "frame " + std::to_string(*counters.frame) + " of " + std::to_string(*counters.frames)
          : "step " + std::to_string(world.stepCount());
  // A frame whose contacts came from the compute shaders says so: a video
  // compared with a CPU one must not pass for it.
  const char* device = world.settings().collisionDevice == CollisionDevice::Gpu ? "   collision on the gpu" : "";
  std::snprintf(line, sizeof line, "%s   %s   t = %.3f s%s", scene.name.c_str(), progress.c_str(), world.time(), device);
  const float scale = counters.imageWidth >= 800 ? 2.0f : 1.0f;
  out.texts.push_back({6 * scale, 5 * scale, scale, line, {1, 1, 1, 1}});
  const StepStats& stats = world.lastStepStats();
  // Candidate pairs come from a step's broad phase: before the first step
  // there are none to count, which "pairs 0" beside frame 0's contacts would hide.
  const std::string pairs = world.stepCount() == 0 ? "-" : std::to_string(stats.candidatePairs);
  std::size_t present = 0;
  for (BodyId id = 0; id < world.bodyCount(); ++id) present += world.isPresent(id) ? 1 : 0;
  // A scene that adds or removes bodies says how many of them are in the run now.
  const std::string bodies =
      present == world.bodyCount() ? std::to_string(present) : std::to_string(present) + " of " + std::to_string(world.bodyCount());
  const int length = std::snprintf(line, sizeof line, "bodies %s   pairs %s   contacts %d", bodies.c_str(),
                                   pairs.c_str(), contactPairCount(world.shownContacts()));
  if (counters.stepMs && length > 0 && static_cast<std::size_t>(length) < sizeof line)
    std::snprintf(line + length, sizeof line - length, "   step %.3f ms", *counters.stepMs);
  out.texts.push_back({6 * scale, 17 * scale, scale, line, {0.85f, 0.85f, 0.85f, 1}});
}

}  // namespace physdbg::viewer
