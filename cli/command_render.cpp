// physdbg render: simulates a scene, writes its frames as PNGs and, with
// --video, encodes them with ffmpeg.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/collision_device.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/numerical_faults.h"
#include "cli/output_folder.h"
#include "cli/progress_bar.h"
#include "cli/view_options.h"
#include "render/renderer.h"
#include "reports/child_process.h"
#include "scenes/scene.h"
#include "viewer/frame_pipeline.h"
#include "viewer/scene_frames.h"

namespace physdbg::cli {
namespace {

// The image2 demuxer reads '%' as a pattern: a literal one is written "%%".
std::string escapePercent(const std::string& text) {
  std::string escaped;
  for (const char c : text) escaped += c == '%' ? std::string("%%") : std::string(1, c);
  return escaped;
}

// ffmpeg as an argument vector (reports/child_process.h): no shell sees the
// folder or the video path. "file:" makes ffmpeg take each path literally: not
// as a protocol ("http:..."), nor as an option when it starts with '-'.
// -frames:v stops at this run's last frame: a frame file after it, left by
// another run, never reaches the video.
ChildCommand videoCommand(const std::string& ffmpeg, const std::string& directory, const std::string& video,
                          double framesPerSecond, const FrameRange& frames) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", framesPerSecond);
  ChildCommand command;
  command.program = ffmpeg;
  command.arguments = {"-nostdin", "-y", "-loglevel", "error", "-framerate", rate, "-start_number",
                       std::to_string(frames.first), "-f", "image2", "-i",
                       "file:" + escapePercent(directory) + "/frame_%05d.png", "-frames:v",
                       std::to_string(frames.count()), "-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf",
                       "pad=ceil(iw/2)*2:ceil(ih/2)*2", "file:" + video};
  return command;
}

void encodeVideo(const std::string& ffmpeg, const std::string& directory, const std::string& video,
                 double framesPerSecond, const FrameRange& frames) {
  const ChildExit exit = runChild(videoCommand(ffmpeg, directory, video, framesPerSecond, frames));
  if (!exit.succeeded()) throw std::runtime_error("ffmpeg failed to write '" + video + "' (" + exit.describe() + ")");
}

// Finds ffmpeg on PATH and checks the video path before any frame is drawn.
// Like -o, --video creates its folder (out/ on a fresh checkout).
std::string prepareVideo(const std::string& video) {
  const std::optional<std::string> ffmpeg = findExecutable("ffmpeg");
  if (!ffmpeg)
    throw UsageError("--video: ffmpeg is not installed (apt-get install ffmpeg); the PNG frames need no ffmpeg");
  const std::filesystem::path folder = std::filesystem::path(video).parent_path();
  if (!folder.empty()) prepareOutputDirectory(folder.string(), "--video");
  checkOutputFile(video, "--video");
  return *ffmpeg;
}

// Frame files of an earlier run would pass for this run's. A whole run owns
// the folder and clears every frame file; a slice (--frames A:B) shares the
// folder with the processes drawing the other slices, so it clears only its
// own frames A..B-1.
void removeEarlierFrames(const std::string& directory, const FrameRange& frames) {
  const int removed = frames.slice ? removeFrames(directory, frames.first, frames.last, "-o")
                                   : removeFrames(directory, 0, std::numeric_limits<int>::max(), "-o");
  if (removed > 0)
    std::printf("removed %d frame file%s of an earlier run from %s\n", removed, removed == 1 ? "" : "s",
                directory.c_str());
}

// Per frame. Physics runs a frame ahead on its own thread and encoding on
// others, so the stages overlap: wall is what a frame costs.
void printStageTimes(const viewer::FrameStageTimes& times, const viewer::SceneFrames& frames) {
  const double perFrame = 1e3 / std::max(1, times.frames);
  std::printf("per frame: simulate %.3f ms, frame assembly %.3f ms, draw %.3f ms, read-back %.3f ms, PNG encode "
              "%.3f ms, wall %.3f ms\n",
              perFrame * frames.simulateSeconds(), perFrame * (frames.drawSeconds() + times.prepare),
              perFrame * times.draw, perFrame * times.readBack, perFrame * (times.encode + times.write),
              perFrame * times.wall);
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
  CommandSpec spec{
      "render",
      "SCENE [-o DIR] [--frames N|A:B] [--size WxH] [--layers LIST] [--steps-per-frame K] [--video FILE.mp4] "
      "[camera options] [--backend osmesa|egl]",
      "Simulates SCENE (a built-in name or a scene file) and writes DIR/frame_00000.png, frame_00001.png, ...\n"
      "Frame 0 is the initial state; each later frame advances K steps. With --frames A:B only frames A..B-1\n"
      "are drawn (earlier ones are simulated), so several processes can render one run into one folder.\n"
      "Frame files of an earlier run are removed first: every frame_NNNNN.png in DIR, or with --frames A:B\n"
      "only frames A..B-1 (the other slices belong to the other processes).",
      {outputOption("DIR", "output folder (default out/SCENE)"),
       {"--video", "", "FILE.mp4", "also encode the frames into a video with ffmpeg"}},
      1,
      1};
  addOptions(spec, {OptionGroup::SceneFrames, OptionGroup::ImageSize, OptionGroup::SceneLayers, OptionGroup::Focus,
                    OptionGroup::Camera, OptionGroup::Backend, OptionGroup::Solver, OptionGroup::Threads,
                    OptionGroup::Collision});
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  const ViewOptions options = readViewOptions(*parsed, scene);
  const std::string outputDirectory = parsed->value("--output", sceneOutputFolder(scene.name));
  const std::string video = parsed->value("--video");
  const std::string ffmpeg = parsed->has("--video") ? prepareVideo(video) : "";
  prepareOutputDirectory(outputDirectory);
  removeEarlierFrames(outputDirectory, options.frames);

  std::shared_ptr<CollisionOffload> collision = collisionOffloadFor(scene, readBackend(*parsed));
  viewer::SceneFrames frames = asUsageError(
      [&] { return viewer::SceneFrames(scene, options, viewer::FramePurpose::Show, std::move(collision)); });
  render::Renderer renderer({options.width, options.height, options.samples, readBackend(*parsed)});
  ProgressBar progress("render " + scene.name, options.frames.count());
  viewer::FramePipelineOptions pipeline;
  pipeline.first = options.frames.first;
  pipeline.last = options.frames.last;
  const viewer::FrameStageTimes times = asUsageError([&] {
    return viewer::runFramePipeline(
        pipeline, [&](int index) { return frames.frame(index); }, renderer,
        [&](int index) { return framePath(outputDirectory, index); }, [&](int done) { progress.update(done); });
  });
  progress.finish();
  std::printf("wrote %d frames (%dx%d) to %s\n", options.frames.count(), options.width, options.height,
              outputDirectory.c_str());
  printStageTimes(times, frames);
  if (!ffmpeg.empty()) {
    encodeVideo(ffmpeg, outputDirectory, video, 1.0 / (scene.world.dt * options.stepsPerFrame), options.frames);
    std::printf("wrote video %s\n", video.c_str());
  }
  viewer::reportBlankLayers("render", options, frames.layerCounts());
  viewer::reportLabelsLeftOut("render", frames.labelsLeftOut());
  return reportNumericalFaults("render", frames.world());
}

}  // namespace physdbg::cli
