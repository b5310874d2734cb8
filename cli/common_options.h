#pragma once
// The options several commands take (--size, --backend, --frames, --layers,
// the camera, --steps, -o ...) are declared and parsed here once, so that each
// means, defaults and fails the same way in every command that takes it: a
// bad value is a UsageError (exit code 2) naming the option and the value.
// A command lists the groups it takes and adds its own options.
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/arguments.h"
#include "debugdraw/primitives.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/view_options.h"

namespace physdbg::cli {

using viewer::CameraOptions;
using viewer::FrameRange;
using viewer::ViewOptions;

// Where two commands' defaults differ (a scene's run or a recording; a frame
// or a tree panel), a group comes in one variant each: the same option, the
// same parser, a help text that states that command's default.
enum class OptionGroup {
  SceneFrames,     // --frames (default the scene's run), --steps-per-frame, --no-timing
  RecordedFrames,  // --frames (default every recorded frame)
  ImageSize,       // --size (default 1280x720)
  PanelSize,       // --size of each tree panel (default 640x480)
  SceneLayers,     // --layers (default the scene's), --tree-depth
  RecordedLayers,  // --layers (default those the recording showed), --tree-depth
  Focus,           // --highlight, --labels, --samples
  Camera,          // --follow, --eye, --target, --fov, --ortho
  Backend,         // --backend
  RunSteps,        // --steps (default the scene's steps)
  TreeSteps,       // --steps after the insertions (default none)
  Solver,          // --solver seed|sequential_impulse (default the scene's)
  Threads,         // --threads N (default the scene's, else every core)
  Collision,       // --collision cpu|gpu (default the scene's, else cpu)
};

// The --size defaults: a frame, and each of the tree's two panels.
inline constexpr char defaultImageSize[] = "1280x720";
inline constexpr char defaultPanelSize[] = "640x480";
// The --layers of a scene run when neither the option nor the scene names any.
inline constexpr char defaultLayers[] = "shapes,aabbs,overlay";

// Appends the option rows of `groups`, in order, to spec.options.
void addOptions(CommandSpec& spec, std::initializer_list<OptionGroup> groups);

// -o/--output with a command's value name ("DIR", "FILE") and help.
OptionSpec outputOption(const std::string& valueName, const std::string& help);
// The -o value; throws "-o VALUENAME is required" when it is missing.
std::string requiredOutput(const Arguments& arguments, const std::string& valueName);

// --size, or `fallback`: each side and the pixel count within limits.h.
std::pair<int, int> readSize(const Arguments& arguments, const std::string& fallback);
// --backend osmesa|egl (default osmesa).
render::Backend readBackend(const Arguments& arguments);
// --frames, when given.
std::optional<FrameRange> readFrames(const Arguments& arguments);
// --steps-per-frame K (default 1), bounded by limits::maxSteps.
int readStepsPerFrame(const Arguments& arguments);
// --steps N (default `fallback`), bounded by limits::maxSteps.
int readSteps(const Arguments& arguments, int fallback);
// --layers, else `fallback` (a layer list too); throws naming --layers.
debugdraw::LayerSet readLayers(const Arguments& arguments, const std::string& fallback);
// --tree-depth into `options` (needs the tree layer among options.layers;
// `layersFrom` says where those came from, for the message).
void readTreeDepth(const Arguments& arguments, ViewOptions& options, const std::string& layersFrom);
// --follow, --eye, --target, --fov, --ortho (no scene to check --follow against).
CameraOptions readCameraOptions(const Arguments& arguments);
// --solver (or another option naming a solver kind), when given.
std::optional<SolverKind> readSolverKind(const Arguments& arguments, const std::string& option = "--solver");
// --threads N (0..scene_limits::maxThreads; 0 one per core), when given.
std::optional<int> readThreads(const Arguments& arguments);
// --collision cpu|gpu, when given.
std::optional<CollisionDevice> readCollisionDevice(const Arguments& arguments);
// The scene named by the first positional argument (a built-in name or a
// file), with --solver, --threads and --collision, when given, overriding the scene's.
SceneDescription readScene(const Arguments& arguments);
// --highlight A,B,...: distinct body indices, at most limits::maxHighlighted.
std::vector<int> readHighlight(const Arguments& arguments);
// --samples N: 0 (off), 2, 4 or 8.
int readSamples(const Arguments& arguments);

// The value parsers behind them, each throwing a UsageError naming `option`.
// "1280x720" -> {1280, 720}.
std::pair<int, int> parseSize(const std::string& text, const std::string& option);
// "N" (frames 0..N-1) or "A:B" (frames A..B-1, a slice), also rejecting a
// range with no frame in it ("5:5").
FrameRange parseFrameRange(const std::string& text, const std::string& option);
// "A:B" depth range, inclusive; "A:" means no upper limit.
std::pair<int, int> parseDepthRange(const std::string& text, const std::string& option);
// "x,y,z".
debugdraw::Vec3 parseVector(const std::string& text, const std::string& option);
// "shapes,aabbs,...".
debugdraw::LayerSet parseLayerList(const std::string& list, const std::string& option);

}  // namespace physdbg::cli
