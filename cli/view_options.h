#pragma once
// Options shared by `render` and `record`: which frames, which layers, and
// where the camera looks from (viewer/view_options.h). Parsed once, validated
// before any work.
#include <utility>
#include <vector>

#include "cli/arguments.h"
#include "debugdraw/frame_view.h"
#include "debugdraw/primitives.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/view_options.h"

namespace physdbg::cli {

// The plain option structs live with the viewer that draws them.
using viewer::CameraOptions;
using viewer::FrameRange;
using viewer::selectionOf;
using viewer::ViewOptions;

// The option rows for a CommandSpec: every view option (render), or those a
// recording's replay can still change: layers, focus, camera (replay).
std::vector<OptionSpec> viewOptionSpecs();
std::vector<OptionSpec> replayViewOptionSpecs();
// `record` keeps every layer and body: focus and labels are chosen at replay.
std::vector<OptionSpec> recordViewOptionSpecs();

// The camera options alone (replay: no scene to check --follow against).
CameraOptions readCameraOptions(const Arguments& arguments);
// --highlight A,B,...: distinct body indices, at most limits::maxHighlighted.
std::vector<int> readHighlight(const Arguments& arguments);
// --layers LIST; throws UsageError naming the option.
debugdraw::LayerSet readLayerList(const std::string& list, const std::string& option);
// --tree-depth into `options` (needs the tree layer among options.layers).
void readTreeDepth(const Arguments& arguments, ViewOptions& options, const std::string& layersFrom);
// --samples N: 0 (off), 2, 4 or 8.
int readSamples(const Arguments& arguments);

// "N" (frames 0..N-1) or "A:B" (frames A..B-1, a slice). Throws UsageError
// naming `option`, also for a range with no frame in it ("5:5").
FrameRange parseFrameRange(const std::string& text, const std::string& option);
// "A:B" depth range, inclusive; "A:" means no upper limit.
std::pair<int, int> parseDepthRange(const std::string& text, const std::string& option);
// "x,y,z". Throws UsageError naming `option`.
Vec3 parseVector(const std::string& text, const std::string& option);

// --backend osmesa|egl, for the commands that render.
OptionSpec backendOptionSpec();
// The --backend choice (default osmesa); throws UsageError naming the choices.
render::Backend readBackend(const Arguments& arguments);

// Throws UsageError for bad values, including a --follow body the scene lacks.
ViewOptions readViewOptions(const Arguments& arguments, const SceneDescription& scene);

}  // namespace physdbg::cli
