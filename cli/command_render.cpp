#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/png_writer_pool.h"
#include "cli/progress_bar.h"
#include "cli/scene_camera.h"
#include "cli/scene_overlay.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct RenderSettings {
  std::string outputDirectory;
  int frames = 0;
  int stepsPerFrame = 1;
  int width = 1280, height = 720;
  debugdraw::LayerSet layers;
  std::string video;
  bool timing = true;  // step time in the overlay; off for repeatable pictures
};

struct Timings {
  double simulate = 0, draw = 0, encode = 0, wall = 0;
};

// Bad output folders are bad input (exit 2), found before any work is done.
void prepareOutputDirectory(const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw UsageError("-o: cannot create folder '" + directory + "'" + (error ? ": " + error.message() : ""));
  const fs::path probe = fs::path(directory) / ".physdbg-write-test";
  {
    std::ofstream file(probe);
    if (!file) throw UsageError("-o: folder '" + directory + "' is not writable");
  }
  fs::remove(probe, error);
}

bool ffmpegAvailable() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

std::string framePath(const std::string& directory, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return (fs::path(directory) / name).string();
}

void encodeVideo(const std::string& directory, const std::string& video, double framesPerSecond) {
  char command[2048];
  std::snprintf(command, sizeof command,
                "ffmpeg -y -loglevel error -framerate %.6g -i '%s/frame_%%05d.png' -c:v libx264 -pix_fmt yuv420p "
                "-vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' '%s'",
                framesPerSecond, directory.c_str(), video.c_str());
  if (std::system(command) != 0) throw std::runtime_error("ffmpeg failed to write '" + video + "'");
}

RenderSettings readSettings(const Arguments& arguments, const SceneDescription& scene) {
  RenderSettings settings;
  settings.outputDirectory = arguments.value("-o", "out/" + scene.name);
  settings.stepsPerFrame = arguments.positiveInt("--steps-per-frame", 1);
  settings.frames = arguments.positiveInt("--frames", scene.steps / settings.stepsPerFrame + 1);
  std::tie(settings.width, settings.height) = parseSize(arguments.value("--size", "1280x720"), "--size");
  const std::string layers = arguments.value("--layers", scene.layers.value_or("shapes,aabbs,overlay"));
  try {
    settings.layers = debugdraw::parseLayers(layers);
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string("--layers: ") + error.what());
  }
  settings.timing = !arguments.has("--no-timing");
  settings.video = arguments.value("--video");
  if (!settings.video.empty() && !ffmpegAvailable())
    throw UsageError("--video: ffmpeg is not installed (apt-get install ffmpeg); the PNG frames need no ffmpeg");
  return settings;
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
  const CommandSpec spec{
      "render",
      "SCENE [-o DIR] [--frames N] [--size WxH] [--layers LIST] [--steps-per-frame K] [--video FILE.mp4]",
      "Simulates SCENE (a built-in name or a scene file) and writes DIR/frame_00000.png, frame_00001.png, ...\n"
      "Frame 0 is the initial state; each later frame advances K steps.",
      {{"--output", "-o", "DIR", "output folder (default out/SCENE)"},
       {"--frames", "", "N", "number of frames (default: the scene's steps / K + 1)"},
       {"--size", "", "WxH", "image size in pixels (default 1280x720)"},
       {"--layers", "", "LIST", "comma list of debug layers: shapes, wire, aabbs, overlay, ... (default: the "
                                 "scene's, else shapes,aabbs,overlay)"},
       {"--steps-per-frame", "", "K", "simulation steps between frames (default 1)"},
       {"--video", "", "FILE.mp4", "also encode the frames into a video with ffmpeg"},
       {"--no-timing", "", "", "leave the measured step time out of the overlay (repeatable frames)"}},
      1,
      1};
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = resolveScene(parsed->positional()[0]);
  RenderSettings settings = readSettings(*parsed, scene);
  if (parsed->has("--output")) settings.outputDirectory = parsed->value("--output");
  prepareOutputDirectory(settings.outputDirectory);

  World world = buildWorld(scene);
  render::Renderer renderer({settings.width, settings.height, 0});
  const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
  PngWriterPool writers(static_cast<int>(cores - 1), 2 * cores);
  ProgressBar progress("render " + scene.name, settings.frames);

  Timings timings;
  const auto wallStart = Clock::now();
  std::optional<render::Camera> camera;
  double lastStepMs = 0;
  for (int frameIndex = 0; frameIndex < settings.frames; ++frameIndex) {
    auto start = Clock::now();
    if (frameIndex > 0) {
      for (int step = 0; step < settings.stepsPerFrame; ++step) world.step();
      const double seconds = secondsSince(start);
      timings.simulate += seconds;
      lastStepMs = 1e3 * seconds / settings.stepsPerFrame;
    }
    start = Clock::now();
    debugdraw::Frame frame;
    world.emitDebugDraw(settings.layers, frame);
    if (!camera) {
      debugdraw::Frame framing;
      world.emitDebugDraw(debugdraw::parseLayers("shapes"), framing);
      camera = chooseCamera(scene, framing, double(settings.width) / settings.height);
    }
    if (settings.layers.has(debugdraw::Layer::Overlay))
      addOverlay(scene, world,
                 {frameIndex, settings.frames - 1, settings.timing ? std::optional<double>(lastStepMs) : std::nullopt},
                 frame);
    render::Image image = renderer.render(frame, *camera);
    timings.draw += secondsSince(start);
    writers.submit(framePath(settings.outputDirectory, frameIndex), std::move(image));
    progress.update(frameIndex + 1);
  }
  writers.finish();
  progress.finish();
  timings.wall = secondsSince(wallStart);
  timings.encode = writers.encodeSeconds();

  const double frames = settings.frames;
  std::printf("wrote %d frames (%dx%d) to %s\n", settings.frames, settings.width, settings.height,
              settings.outputDirectory.c_str());
  std::printf("per frame: simulate %.3f ms, draw %.3f ms, PNG encode %.3f ms (on %u worker threads), wall %.3f ms\n",
              1e3 * timings.simulate / frames, 1e3 * timings.draw / frames, 1e3 * timings.encode / frames, cores - 1,
              1e3 * timings.wall / frames);
  if (!settings.video.empty()) {
    encodeVideo(settings.outputDirectory, settings.video, 1.0 / (scene.world.dt * settings.stepsPerFrame));
    std::printf("wrote video %s\n", settings.video.c_str());
  }
  for (const NumericalFault& fault : world.numericalFaults())
    std::fprintf(stderr, "physdbg render: body %u: %s at step %d; body frozen\n", fault.body, fault.what.c_str(),
                 fault.step);
  return world.numericalFaults().empty() ? 0 : 1;
}

}  // namespace physdbg::cli
