#pragma once
// What a viewer draws: which frames, which layers, and where the camera looks
// from. Plain data: cli/view_options.h parses and validates it from the command
// line; the golden tests fill it in directly.
#include <optional>
#include <vector>

#include "debugdraw/frame_view.h"
#include "debugdraw/primitives.h"

namespace physdbg::viewer {

struct FrameRange {
  int first = 0, last = 0;  // frames first .. last-1
  // Given as A:B: a slice of a run that other processes may be drawing into
  // the same folder, so this run owns only its own frames there.
  bool slice = false;
  int count() const { return last - first; }
};

// Where the camera looks from; each unset value keeps the framed (or recorded) view's.
struct CameraOptions {
  std::optional<int> follow;  // body index
  std::optional<debugdraw::Vec3> eye, target;
  std::optional<double> fovYDegrees;
  bool orthographic = false;
  bool any() const { return follow || eye || target || fovYDegrees || orthographic; }
};

struct ViewOptions {
  FrameRange frames;
  int runFrames = 0;  // frames in the whole run, of which `frames` may be a slice: the overlay's "of N"
  int stepsPerFrame = 1;
  int width = 1280, height = 720;
  debugdraw::LayerSet layers;
  int treeMinDepth = 0, treeMaxDepth = 1 << 30;
  CameraOptions camera;
  std::vector<int> highlight;  // body indices in focus
  bool labels = false;
  int samples = 0;  // MSAA samples per pixel
  bool timing = true;  // measured step time in the overlay (off: byte-identical frames run after run)
};

// --layers, --tree-depth, --highlight, --labels, --follow and the camera as a
// viewer applies them (debugdraw/frame_view.h).
debugdraw::ViewSelection selectionOf(const ViewOptions& options);

}  // namespace physdbg::viewer
