#include "cli/view_options.h"

#include <cmath>
#include <sstream>

namespace physdbg::cli {
namespace {

int parseIndex(const std::string& text, const std::string& option, const std::string& whole) {
  std::size_t used = 0;
  int value = -1;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || value < 0)
    throw UsageError(option + ": expected non-negative whole numbers, got '" + whole + "'");
  return value;
}

}  // namespace

std::vector<OptionSpec> viewOptionSpecs() {
  return {{"--frames", "", "N|A:B", "frames 0..N-1, or A..B-1 of the full run (default: the scene's steps / K + 1)"},
          {"--size", "", "WxH", "image size in pixels (default 1280x720)"},
          {"--layers", "", "LIST", "comma list of debug layers: shapes, wire, aabbs, fat, tree, contacts, velocities, "
                                   "sleep, pairs, overlay (default: the scene's, else shapes,aabbs,overlay)"},
          {"--tree-depth", "", "A:B", "draw only tree nodes of depth A..B (root 0; 'A:' for no upper limit)"},
          {"--steps-per-frame", "", "K", "simulation steps between frames (default 1)"},
          {"--follow", "", "BODY", "keep body number BODY at the centre of the view"},
          {"--eye", "", "X,Y,Z", "camera position"},
          {"--target", "", "X,Y,Z", "point the camera looks at"},
          {"--fov", "", "DEGREES", "vertical field of view (default 45)"},
          {"--ortho", "", "", "orthographic projection"},
          {"--no-timing", "", "", "leave the measured step time out of the overlay (repeatable frames)"}};
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
    range.last = parseIndex(text, option, text);
  } else {
    range.first = parseIndex(text.substr(0, colon), option, text);
    range.last = parseIndex(text.substr(colon + 1), option, text);
  }
  if (range.last <= range.first)
    throw UsageError(option + ": '" + text + "' selects no frames (A:B renders frames A to B-1)");
  return range;
}

std::pair<int, int> parseDepthRange(const std::string& text, const std::string& option) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw UsageError(option + ": expected A:B, got '" + text + "'");
  const int low = parseIndex(text.substr(0, colon), option, text);
  const std::string upper = text.substr(colon + 1);
  const int high = upper.empty() ? (1 << 30) : parseIndex(upper, option, text);
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
  options.stepsPerFrame = arguments.positiveInt("--steps-per-frame", 1);
  options.frames.last = scene.steps / options.stepsPerFrame + 1;
  if (arguments.has("--frames")) options.frames = parseFrameRange(arguments.value("--frames"), "--frames");
  std::tie(options.width, options.height) = parseSize(arguments.value("--size", "1280x720"), "--size");
  try {
    options.layers = debugdraw::parseLayers(arguments.value("--layers", scene.layers.value_or("shapes,aabbs,overlay")));
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--layers: ") + error.what());
  }
  if (arguments.has("--tree-depth"))
    std::tie(options.treeMinDepth, options.treeMaxDepth) = parseDepthRange(arguments.value("--tree-depth"), "--tree-depth");
  if (arguments.has("--follow")) {
    const std::string body = arguments.value("--follow");
    options.follow = parseIndex(body, "--follow", body);
    if (*options.follow >= static_cast<int>(scene.bodies.size()))
      throw UsageError("--follow: scene '" + scene.name + "' has no body " + body + " (it has " +
                       std::to_string(scene.bodies.size()) + ")");
  }
  if (arguments.has("--eye")) options.eye = parseVector(arguments.value("--eye"), "--eye");
  if (arguments.has("--target")) options.target = parseVector(arguments.value("--target"), "--target");
  if (arguments.has("--fov")) {
    options.fovYDegrees = arguments.positiveDouble("--fov", 45);
    if (*options.fovYDegrees >= 180) throw UsageError("--fov: must be below 180 degrees");
  }
  options.orthographic = arguments.has("--ortho");
  options.timing = !arguments.has("--no-timing");
  return options;
}

}  // namespace physdbg::cli
