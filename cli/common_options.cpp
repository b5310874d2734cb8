#include "cli/common_options.h"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <limits>
#include <sstream>

#include "cli/limits.h"
#include "scenes/scene_limits.h"

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

// The option rows that come in two variants: one name and value name each,
// the help saying the variant's default.
OptionSpec framesOption(const std::string& help) { return {"--frames", "", "N|A:B", help}; }
OptionSpec sizeOption(const std::string& help) { return {"--size", "", "WxH", help}; }
OptionSpec layersOption(const std::string& help) { return {"--layers", "", "LIST", help}; }
OptionSpec treeDepthOption(const std::string& help) {
  return {"--tree-depth", "", "A:B",
          "draw only tree nodes of depth A..B (root 0; 'A:' for no upper limit" + help + ")"};
}
OptionSpec stepsOption(const std::string& help) { return {"--steps", "", "N", help}; }

std::vector<OptionSpec> sceneFramesOptions() {
  return {framesOption("frames 0..N-1, or A..B-1 of the full run (default: the scene's steps / K + 1)"),
          {"--steps-per-frame", "", "K", "simulation steps between frames (default 1)"},
          {"--no-timing", "", "", "leave the measured step time out of the overlay (repeatable frames)"},
          {"--of-run", "", "N|A:B",
           "the --frames of the whole run a slice (--frames A:B) belongs to, so that its overlay counts frames as "
           "that run's does (scripts/render-parallel.sh)"}};
}

std::vector<OptionSpec> focusOptions() {
  return {{"--highlight", "", "A[,B...]",
           "bodies in focus: drawn as they are with their contacts, candidate pairs and tree path to the root; the "
           "rest faded; their state in the overlay"},
          {"--labels", "", "", "body numbers (and scene names) over the bodies"},
          {"--samples", "", "N", "multisample anti-aliasing: 0 (default), 2, 4 or 8 samples per pixel"}};
}

std::vector<OptionSpec> cameraOptions() {
  return {{"--follow", "", "BODY", "keep body number BODY at the centre of the view, marked by corner brackets"},
          {"--eye", "", "X,Y,Z", "camera position"},
          {"--target", "", "X,Y,Z", "point the camera looks at"},
          {"--fov", "", "DEGREES", "vertical field of view (default 45)"},
          {"--ortho", "", "", "orthographic projection"}};
}

std::vector<OptionSpec> optionRows(OptionGroup group) {
  switch (group) {
    case OptionGroup::SceneFrames:
      return sceneFramesOptions();
    case OptionGroup::RecordedFrames:
      return {framesOption("frames 0..N-1 or A..B-1 (default all)")};
    case OptionGroup::ImageSize:
      return {sizeOption(std::string("image size in pixels (default ") + defaultImageSize + ")")};
    case OptionGroup::PanelSize:
      return {sizeOption(std::string("size of each of the two panels (default ") + defaultPanelSize + ")")};
    case OptionGroup::SceneLayers:
      return {layersOption("comma list of debug layers: shapes, wire, aabbs, fat, tree, contacts, velocities, sleep, "
                           "pairs, overlay (default: the scene's, else " +
                           std::string(defaultLayers) + ")"),
              treeDepthOption("; needs the tree layer")};
    case OptionGroup::RecordedLayers:
      return {layersOption("debug layers to show, among those recorded (default: those the recording run showed)"),
              treeDepthOption("")};
    case OptionGroup::Focus:
      return focusOptions();
    case OptionGroup::Camera:
      return cameraOptions();
    case OptionGroup::Backend:
      return {
          {"--backend", "", "osmesa|egl", "GL context: OSMesa (default) or EGL without a surface (Mesa 25.1+, GPUs)"}};
    case OptionGroup::RunSteps:
      return {stepsOption("number of steps (default: the scene's steps)")};
    case OptionGroup::TreeSteps:
      return {stepsOption("then simulate N steps and show reinsertions that rotate")};
    case OptionGroup::Solver:
      return {{"--solver", "", "seed|sequential_impulse",
               "contact solver, overriding the scene's: the design's one-point response, or sequential impulses"}};
    case OptionGroup::Threads:
      return {{"--threads", "", "N",
               "threads each step may use, overriding the scene's: 0 one per core (the default), 1 none spawned; "
               "results are bit-identical for every N"}};
    case OptionGroup::Collision:
      return {{"--collision", "", "cpu|gpu",
               "where collision detection runs, overriding the scene's: cpu (the default), or compute shaders "
               "(GL 4.3) in a --backend context for the broad phase and sphere, box and capsule pairs"}};
  }
  return {};
}

}  // namespace

void addOptions(CommandSpec& spec, std::initializer_list<OptionGroup> groups) {
  for (const OptionGroup group : groups)
    for (OptionSpec& row : optionRows(group)) spec.options.push_back(std::move(row));
}

std::optional<SolverKind> readSolverKind(const Arguments& arguments, const std::string& option) {
  if (!arguments.has(option)) return std::nullopt;
  const std::string name = arguments.value(option);
  for (const SolverKind kind : {SolverKind::Seed, SolverKind::SequentialImpulse})
    if (name == solverKindName(kind)) return kind;
  throw UsageError(option + ": expected seed or sequential_impulse, got '" + name + "'");
}

std::optional<int> readThreads(const Arguments& arguments) {
  if (!arguments.has("--threads")) return std::nullopt;
  return parseIndex(arguments.value("--threads"), "--threads", arguments.value("--threads"), scene_limits::maxThreads);
}

std::optional<CollisionDevice> readCollisionDevice(const Arguments& arguments) {
  if (!arguments.has("--collision")) return std::nullopt;
  const std::string name = arguments.value("--collision");
  for (const CollisionDevice device : {CollisionDevice::Cpu, CollisionDevice::Gpu})
    if (name == collisionDeviceName(device)) return device;
  throw UsageError("--collision: expected cpu or gpu, got '" + name + "'");
}

SceneDescription readScene(const Arguments& arguments) {
  SceneDescription scene = resolveScene(arguments.positional()[0]);
  for (const std::string& note : scene.notes) std::cerr << "note: " << note << "\n";
  if (const std::optional<SolverKind> kind = readSolverKind(arguments)) scene.world.solver.kind = *kind;
  if (const std::optional<int> threads = readThreads(arguments)) scene.world.threads = *threads;
  if (const std::optional<CollisionDevice> device = readCollisionDevice(arguments))
    scene.world.collisionDevice = *device;
  return scene;
}

OptionSpec outputOption(const std::string& valueName, const std::string& help) {
  return {"--output", "-o", valueName, help};
}

std::string requiredOutput(const Arguments& arguments, const std::string& valueName) {
  if (!arguments.has("--output")) throw UsageError("-o " + valueName + " is required");
  return arguments.value("--output");
}

std::pair<int, int> readSize(const Arguments& arguments, const std::string& fallback) {
  return parseSize(arguments.value("--size", fallback), "--size");
}

render::Backend readBackend(const Arguments& arguments) {
  try {
    return render::parseBackend(arguments.value("--backend", "osmesa"));
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--backend: ") + error.what());
  }
}

std::optional<FrameRange> readFrames(const Arguments& arguments) {
  if (!arguments.has("--frames")) return std::nullopt;
  return parseFrameRange(arguments.value("--frames"), "--frames");
}

int readStepsPerFrame(const Arguments& arguments) {
  return arguments.positiveInt("--steps-per-frame", 1, static_cast<int>(limits::maxSteps));
}

int readSteps(const Arguments& arguments, int fallback) {
  return arguments.positiveInt("--steps", fallback, static_cast<int>(limits::maxSteps));
}

debugdraw::LayerSet readLayers(const Arguments& arguments, const std::string& fallback) {
  return parseLayerList(arguments.value("--layers", fallback), "--layers");
}

void readTreeDepth(const Arguments& arguments, ViewOptions& options, const std::string& layersFrom) {
  if (!arguments.has("--tree-depth")) return;
  if (!options.layers.has(debugdraw::Layer::Tree))
    throw UsageError("--tree-depth: it limits the 'tree' layer, which is not among the layers (" +
                     debugdraw::layerNames(options.layers) + ", from " + layersFrom + "); add tree to --layers");
  std::tie(options.treeMinDepth, options.treeMaxDepth) =
      parseDepthRange(arguments.value("--tree-depth"), "--tree-depth");
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

std::pair<int, int> parseSize(const std::string& text, const std::string& option) {
  const auto x = text.find('x');
  int width = 0, height = 0;
  const auto parsePart = [](const std::string& part, int& out) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), out);
    return error == std::errc() && end == part.data() + part.size() && !part.empty();
  };
  const auto inRange = [](int side) { return side >= limits::minImageSide && side <= limits::maxImageSide; };
  if (x == std::string::npos || !parsePart(text.substr(0, x), width) || !parsePart(text.substr(x + 1), height) ||
      !inRange(width) || !inRange(height) || static_cast<long long>(width) * height > limits::maxImagePixels)
    throw UsageError(option + " must be WIDTHxHEIGHT with each side from " + std::to_string(limits::minImageSide) +
                     " to " + std::to_string(limits::maxImageSide) + " and at most " +
                     std::to_string(limits::maxImagePixels) + " pixels, got '" + text + "'");
  return {width, height};
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

debugdraw::Vec3 parseVector(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  debugdraw::Vec3 v;
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x() >> comma1 >> v.y() >> comma2 >> v.z()) || comma1 != ',' || comma2 != ',' || !in.eof() ||
      !v.allFinite())
    throw UsageError(option + ": expected X,Y,Z, got '" + text + "'");
  return v;
}

debugdraw::LayerSet parseLayerList(const std::string& list, const std::string& option) {
  try {
    return debugdraw::parseLayers(list);
  } catch (const std::invalid_argument& error) {
    throw UsageError(option + ": " + error.what());
  }
}

}  // namespace physdbg::cli
