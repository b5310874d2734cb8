#include "cli/scene_overlay.h"

#include <cstdio>
#include <string>

namespace physdbg::cli {

void addOverlay(const SceneDescription& scene, const World& world, const OverlayCounters& counters,
                debugdraw::Frame& out) {
  char line[256];
  const std::string progress = counters.frame && counters.frames
                                   ? "frame " + std::to_string(*counters.frame) + "/" + std::to_string(*counters.frames)
                                   : "step " + std::to_string(world.stepCount());
  std::snprintf(line, sizeof line, "%s   %s   t = %.3f s", scene.name.c_str(), progress.c_str(), world.time());
  out.texts.push_back({12, 10, 2, line, {1, 1, 1, 1}});
  if (counters.stepMs)
    std::snprintf(line, sizeof line, "bodies %zu   step %.3f ms", world.bodyCount(), *counters.stepMs);
  else
    std::snprintf(line, sizeof line, "bodies %zu", world.bodyCount());
  out.texts.push_back({12, 34, 2, line, {0.85f, 0.85f, 0.85f, 1}});
}

}  // namespace physdbg::cli
