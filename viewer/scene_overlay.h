#pragma once
// The overlay text of a rendered frame. Without a step time the text depends
// only on the simulation, so golden images can include it.
#include <optional>

#include "debugdraw/primitives.h"
#include "scenes/scene.h"

namespace physdbg::viewer {

struct OverlayCounters {
  // "frame 3 of 60" when both are given: `frames` counts the whole run, not
  // the slice one process draws, so every slice of a shared run reads alike.
  std::optional<int> frame, frames;
  std::optional<double> stepMs;      // measured wall-clock time: leave empty for repeatable pictures
  int imageWidth = 1280;             // text is drawn at half size below 800 pixels, so it fits
};

void addOverlay(const SceneDescription& scene, const World& world, const OverlayCounters& counters,
                debugdraw::Frame& out);

}  // namespace physdbg::viewer
