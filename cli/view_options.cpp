#include "cli/view_options.h"

#include <algorithm>

#include "cli/limits.h"

namespace physdbg::cli {
namespace {

// Frames 0 .. steps / K: the scene's own run, when it fits the frame limit.
FrameRange defaultFrames(const SceneDescription& scene, int stepsPerFrame) {
  const long long last = scene.steps / stepsPerFrame + 1;
  if (last > limits::maxFrames)
    throw UsageError("--frames: the scene's " + std::to_string(scene.steps) + " steps at " +
                     std::to_string(stepsPerFrame) + " per frame make " + std::to_string(last) + " frames, more than " +
                     std::to_string(limits::maxFrames) + "; choose a range with --frames or raise --steps-per-frame");
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

// --of-run: the whole run a slice belongs to, which must contain the slice.
FrameRange wholeRun(const Arguments& arguments, const FrameRange& frames) {
  if (!arguments.has("--of-run")) return frames;
  if (!frames.slice) throw UsageError("--of-run: it belongs with a slice, --frames A:B");
  const FrameRange run = parseFrameRange(arguments.value("--of-run"), "--of-run");
  if (frames.first < run.first || frames.last > run.last)
    throw UsageError("--of-run: the slice --frames " + std::to_string(frames.first) + ":" +
                     std::to_string(frames.last) + " is not inside the run '" + arguments.value("--of-run") + "'");
  return run;
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

}  // namespace

void readDrawChoices(const Arguments& arguments, ViewOptions& options, const SceneDescription* scene) {
  options.camera = readCameraOptions(arguments);
  options.highlight = readHighlight(arguments);
  if (scene) {
    for (int body : options.highlight) checkBodyIndex(body, "--highlight", *scene);
    if (options.camera.follow) checkBodyIndex(*options.camera.follow, "--follow", *scene);
  }
  options.labels = arguments.has("--labels");
  options.samples = readSamples(arguments);
}

ViewOptions readViewOptions(const Arguments& arguments, const SceneDescription& scene) {
  ViewOptions options;
  options.stepsPerFrame = readStepsPerFrame(arguments);
  const std::optional<FrameRange> frames = readFrames(arguments);
  options.frames = frames ? *frames : defaultFrames(scene, options.stepsPerFrame);
  checkRunLength(options.frames, options.stepsPerFrame);
  options.runFrames = runFrameCount(wholeRun(arguments, options.frames), scene, options.stepsPerFrame);
  std::tie(options.width, options.height) = readSize(arguments, defaultImageSize);
  options.layers = readLayers(arguments, scene.layers.value_or(defaultLayers));
  readTreeDepth(arguments, options, layersSource(arguments, scene));
  readDrawChoices(arguments, options, &scene);
  options.timing = !arguments.has("--no-timing");
  return options;
}

}  // namespace physdbg::cli
