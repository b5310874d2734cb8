#include "cli/view_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "cli/limits.h"

namespace physdbg::cli {
namespace {

// A whole number 0..maximum, digits only: no sign, no spaces, no overflow.
int parseIndex(const std::string& text, const std::string& option, const std::string& whole, int maximum) {
  int value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0 || value > maximum)
    throw UsageError(option + ": expected whole numbers from 0 to " + std::to_string(maximum) + ", got '" + whole +
                     "'");
  return value;
}

// Frames 0 .. steps / K: the scene's own run, when it fits the frame limit.
FrameRange defaultFrames(const SceneDescription& scene, int stepsPerFrame) {
  const long long last = scene.steps / stepsPerFrame + 1;
  if (last > limits::maxFrames)
    throw UsageError("--frames: the scene's " + std::to_string(scene.steps) + " steps at " +
                     std::to_string(stepsPerFrame) + " per frame make " + std::to_string(last) +
                     " frames, more than " + std::to_string(limits::maxFrames) +
                     "; choose a range with --frames or raise --steps-per-frame");
  return {0, static_cast<int>(last)};
}

// Reaching the last frame simulates (last - 1) x K steps; bounded, computed without overflow.
void checkRunLength(const FrameRange& frames, int stepsPerFrame) {
  const long long steps = static_cast<long long>(frames.last - 1) * stepsPerFrame;
  if (steps > limits::maxSteps)
    throw UsageError("--frames/--steps-per-frame: frame " + std::to_string(frames.last - 1) + " at " +
                     std::to_string(stepsPerFrame) + " steps per frame is " + std::to_string(steps) +
                     " steps in, more than " + std::to_string(limits::maxSteps));
}

// The whole run's frame count: N for --frames N; for a slice A:B the scene's
// own run, or B when the slice reaches past it (not rejected: a user may
// render past the scene's steps).
int runFrameCount(const FrameRange& frames, const SceneDescription& scene, int stepsPerFrame) {
  if (!frames.slice) return frames.last;
  const long long sceneFrames = scene.steps / stepsPerFrame + 1;
  return static_cast<int>(std::max<long long>(sceneFrames, frames.last));
}

void checkBodyIndex(int body, const std::string& option, const SceneDescription& scene) {
  if (body >= static_cast<int>(scene.bodies.size()))
    throw UsageError(option + ": scene '" + scene.name + "' has no body " + std::to_string(body) + " (it has " +
                     std::to_string(scene.bodies.size()) + ")");
}

// Where the layer list came from, for messages.
std::string layersSource(const Arguments& arguments, const SceneDescription& scene) {
  return arguments.has("--layers") ? "--layers" : scene.layers ? "the scene's" : "the default";
}

std::vector<OptionSpec> cameraOptionSpecs() {
  return {{"--follow", "", "BODY", "keep body number BODY at the centre of the view, marked by corner brackets"},
          {"--eye", "", "X,Y,Z", "camera position"},
          {"--target", "", "X,Y,Z", "point the camera looks at"},
          {"--fov", "", "DEGREES", "vertical field of view (default 45)"},
          {"--ortho", "", "", "orthographic projection"}};
}

std::vector<OptionSpec> focusOptionSpecs() {
  return {{"--highlight", "", "A[,B...]",
           "bodies in focus: drawn as they are with their contacts, candidate pairs and tree path to the root; the "
           "rest faded; their state in the overlay"},
          {"--labels", "", "", "body numbers (and scene names) over the bodies"},
          {"--samples", "", "N", "multisample anti-aliasing: 0 (default), 2, 4 or 8 samples per pixel"}};
}

}  // namespace

debugdraw::LayerSet readLayerList(const std::string& list, const std::string& option) {
  try {
    return debugdraw::parseLayers(list);
  } catch (const std::invalid_argument& error) {
    throw UsageError(option + ": " + error.what());
  }
}

void readTreeDepth(const Arguments& arguments, ViewOptions& options, const std::string& layersFrom) {
  if (!arguments.has("--tree-depth")) return;
  if (!options.layers.has(debugdraw::Layer::Tree))
    throw UsageError("--tree-depth: it limits the 'tree' layer, which is not among the layers (" +
                     debugdraw::layerNames(options.layers) + ", from " + layersFrom + "); add tree to --layers");
  std::tie(options.treeMinDepth, options.treeMaxDepth) = parseDepthRange(arguments.value("--tree-depth"), "--tree-depth");
}

CameraOptions readCameraOptions(const Arguments& arguments) {
  CameraOptions camera;
  if (arguments.has("--follow")) {
    const std::string body = arguments.value("--follow");
    camera.follow = parseIndex(body, "--follow", body, std::numeric_limits<int>::max());
  }
  if (arguments.has("--eye")) camera.eye = parseVector(arguments.value("--eye"), "--eye");
  if (arguments.has("--target")) camera.target = parseVector(arguments.value("--target"), "--target");
  if (arguments.has("--fov")) {
    camera.fovYDegrees = arguments.positiveDouble("--fov", 45);
    if (*camera.fovYDegrees >= 180) throw UsageError("--fov: must be below 180 degrees");
  }
  camera.orthographic = arguments.has("--ortho");
  return camera;
}

std::vector<int> readHighlight(const Arguments& arguments) {
  if (!arguments.has("--highlight")) return {};
  const std::string list = arguments.value("--highlight");
  std::vector<int> bodies;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const int body = parseIndex(item, "--highlight", list, std::numeric_limits<int>::max());
    if (std::find(bodies.begin(), bodies.end(), body) != bodies.end())
      throw UsageError("--highlight: body " + item + " is given twice in '" + list + "'");
    if (bodies.size() == static_cast<std::size_t>(limits::maxHighlighted))
      throw UsageError("--highlight: at most " + std::to_string(limits::maxHighlighted) + " bodies");
    bodies.push_back(body);
  }
  if (bodies.empty() || list.back() == ',') throw UsageError("--highlight: expected A[,B...], got '" + list + "'");
  return bodies;
}

int readSamples(const Arguments& arguments) {
  if (!arguments.has("--samples")) return 0;
  const std::string text = arguments.value("--samples");
  if (text != "0" && text != "2" && text != "4" && text != "8")
    throw UsageError("--samples: expected 0, 2, 4 or 8, got '" + text + "'");
  return std::stoi(text);
}

std::vector<OptionSpec> recordViewOptionSpecs() {
  std::vector<OptionSpec> specs;
  for (const OptionSpec& spec : viewOptionSpecs()) {
    bool focus = false;
    for (const OptionSpec& focusSpec : focusOptionSpecs()) focus = focus || focusSpec.name == spec.name;
    if (!focus) specs.push_back(spec);
  }
  return specs;
}

std::vector<OptionSpec> replayViewOptionSpecs() {
  std::vector<OptionSpec> specs = {
      {"--layers", "", "LIST", "debug layers to show, among those recorded (default: those the recording run showed)"},
      {"--tree-depth", "", "A:B", "draw only tree nodes of depth A..B (root 0; 'A:' for no upper limit)"}};
  for (auto& group : {focusOptionSpecs(), cameraOptionSpecs()}) specs.insert(specs.end(), group.begin(), group.end());
  return specs;
}

std::vector<OptionSpec> viewOptionSpecs() {
  std::vector<OptionSpec> specs = {{"--frames", "", "N|A:B", "frames 0..N-1, or A..B-1 of the full run (default: the scene's steps / K + 1)"},
          {"--size", "", "WxH", "image size in pixels (default 1280x720)"},
          {"--layers", "", "LIST", "comma list of debug layers: shapes, wire, aabbs, fat, tree, contacts, velocities, "
                                   "sleep, pairs, overlay (default: the scene's, else shapes,aabbs,overlay)"},
          {"--tree-depth", "", "A:B",
           "draw only tree nodes of depth A..B (root 0; 'A:' for no upper limit; needs the tree layer)"},
          {"--steps-per-frame", "", "K", "simulation steps between frames (default 1)"},
          {"--no-timing", "", "", "leave the measured step time out of the overlay (repeatable frames)"}};
  for (auto& group : {focusOptionSpecs(), cameraOptionSpecs()}) specs.insert(specs.end(), group.begin(), group.end());
  return specs;
}

OptionSpec backendOptionSpec() {
  return {"--backend", "", "osmesa|egl", "GL context: OSMesa (default) or EGL without a surface (Mesa 25.1+, GPUs)"};
}

render::Backend readBackend(const Arguments& arguments) {
  try {
    return render::parseBackend(arguments.value("--backend", "osmesa"));
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--backend: ") + error.what());
  }
}

FrameRange parseFrameRange(const std::string& text, const std::string& option) {
  const std::size_t colon = text.find(':');
  FrameRange range;
  if (colon == std::string::npos) {
    range.last = parseIndex(text, option, text, limits::maxFrames);
  } else {
    range.first = parseIndex(text.substr(0, colon), option, text, limits::maxFrames);
    range.last = parseIndex(text.substr(colon + 1), option, text, limits::maxFrames);
    range.slice = true;
  }
  if (range.last <= range.first)
    throw UsageError(option + ": '" + text + "' selects no frames (A:B renders frames A to B-1)");
  return range;
}

std::pair<int, int> parseDepthRange(const std::string& text, const std::string& option) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw UsageError(option + ": expected A:B, got '" + text + "'");
  const int low = parseIndex(text.substr(0, colon), option, text, 1 << 30);
  const std::string upper = text.substr(colon + 1);
  const int high = upper.empty() ? (1 << 30) : parseIndex(upper, option, text, 1 << 30);
  if (high < low) throw UsageError(option + ": '" + text + "' is an empty depth range");
  return {low, high};
}

Vec3 parseVector(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  Vec3 v;
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x() >> comma1 >> v.y() >> comma2 >> v.z()) || comma1 != ',' || comma2 != ',' || !in.eof() ||
      !v.allFinite())
    throw UsageError(option + ": expected X,Y,Z, got '" + text + "'");
  return v;
}

ViewOptions readViewOptions(const Arguments& arguments, const SceneDescription& scene) {
  ViewOptions options;
  options.stepsPerFrame = arguments.positiveInt("--steps-per-frame", 1, static_cast<int>(limits::maxSteps));
  options.frames = arguments.has("--frames") ? parseFrameRange(arguments.value("--frames"), "--frames")
                                             : defaultFrames(scene, options.stepsPerFrame);
  checkRunLength(options.frames, options.stepsPerFrame);
  options.runFrames = runFrameCount(options.frames, scene, options.stepsPerFrame);
  std::tie(options.width, options.height) = parseSize(arguments.value("--size", "1280x720"), "--size");
  options.layers = readLayerList(arguments.value("--layers", scene.layers.value_or("shapes,aabbs,overlay")), "--layers");
  readTreeDepth(arguments, options, layersSource(arguments, scene));
  options.camera = readCameraOptions(arguments);
  options.highlight = readHighlight(arguments);
  for (int body : options.highlight) checkBodyIndex(body, "--highlight", scene);
  if (options.camera.follow) checkBodyIndex(*options.camera.follow, "--follow", scene);
  options.labels = arguments.has("--labels");
  options.samples = readSamples(arguments);
  options.timing = !arguments.has("--no-timing");
  return options;
}

}  // namespace physdbg::cli
