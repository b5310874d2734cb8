// physdbg bench render: frames per second end to end for a ~1000-body scene
// at 1280x720 with every 3D layer: simulate one step, emit and draw the
// frame, read it back, encode and write the PNG. The run is made twice from
// the same start with the viewer's frame pipeline (viewer/frame_pipeline.h):
// serially, which splits a frame into its stages without them competing for
// the cores, and pipelined as `physdbg render` runs, whose wall time is the
// figure (`ours_ms`, `frames_per_second`). The drawing thread's waits name the
// stage that bounds the pipelined run. It runs once per engine thread count
// (the step's own threads compete with the pipeline's on a small machine).
// There is no peer: the record's peer fields are empty.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "debugdraw/recording.h"
#include "engine/debug/world_debug_draw.h"
#include "scenes/stacking_scenes.h"
#include "viewer/frame_pipeline.h"
#include "viewer/scene_frames.h"

namespace physdbg::bench {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

int cores() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

struct RenderBenchSize {
  int pyramidBase, width, height, frames;
};

RenderBenchSize benchSize(bool quick) {
  if (quick) return {8, 320, 180, 3};
  return {44, 1280, 720, 60};  // 44 at the base: 990 boxes and a floor
}

// A scratch folder for the frame files, removed with everything in it.
class ScratchFolder {
 public:
  ScratchFolder()
      : path_(std::filesystem::temp_directory_path() / ("physdbg-render-bench-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  std::string frame(int index) const { return (path_ / ("frame_" + std::to_string(index) + ".png")).string(); }

 private:
  std::filesystem::path path_;
};

// The world and what producing its frames cost, on the producing thread.
class BenchFrames {
 public:
  BenchFrames(const RenderBenchSize& size, int engineThreads) : world_(buildWorld(scene(size, engineThreads))) {
    debugdraw::Frame framing;
    emitDebugDraw(world_, debugdraw::parseLayers("shapes"), framing);
    view_ = viewer::toView(
        render::frameBoundsCamera(render::frameBounds(framing), double(size.width) / size.height));
  }

  // One step, then every 3D layer.
  debugdraw::RecordedFrame frame(int index) {
    auto start = Clock::now();
    world_.step();
    simulateSeconds_ += secondsSince(start);
    start = Clock::now();
    debugdraw::RecordedFrame out;
    out.index = index;
    out.view = view_;
    emitDebugDraw(world_, layers_, out.frame);
    emitSeconds_ += secondsSince(start);
    return out;
  }

  long long bodyCount() const { return static_cast<long long>(world_.bodyCount()); }
  double simulateSeconds() const { return simulateSeconds_; }
  double emitSeconds() const { return emitSeconds_; }

 private:
  static SceneDescription scene(const RenderBenchSize& size, int engineThreads) {
    SceneDescription description = pyramidScene(size.pyramidBase);
    description.world.threads = engineThreads;
    return description;
  }

  World world_;
  debugdraw::View view_;
  debugdraw::LayerSet layers_ = debugdraw::parseLayers("shapes,aabbs,fat,tree,contacts,velocities,pairs");
  double simulateSeconds_ = 0, emitSeconds_ = 0;
};

struct PipelineRun {
  viewer::FrameStageTimes times;
  double simulateSeconds = 0, emitSeconds = 0;
  long long bodies = 0;
};

PipelineRun runPipeline(const RenderBenchSize& size, int engineThreads, viewer::PipelineMode mode,
                        render::Renderer& renderer) {
  const ScratchFolder folder;
  BenchFrames frames(size, engineThreads);
  viewer::FramePipelineOptions options;
  options.mode = mode;
  options.last = size.frames;
  PipelineRun run;
  run.times = viewer::runFramePipeline(
      options, [&](int index) { return frames.frame(index); }, renderer,
      [&](int index) { return folder.frame(index); });
  run.simulateSeconds = frames.simulateSeconds();
  run.emitSeconds = frames.emitSeconds();
  run.bodies = frames.bodyCount();
  return run;
}

// The stage the pipelined run waited on most: physics when the drawing
// thread waited for frames, encoding when it waited for the encoders, else
// drawing itself.
std::string boundBy(const viewer::FrameStageTimes& times) {
  const double drawing = times.prepare + times.draw + times.readBack;
  if (times.waitForFrame > times.waitForEncoder && times.waitForFrame > 0.1 * drawing) return "simulate";
  if (times.waitForEncoder > 0.1 * drawing) return "encode";
  return "draw";
}

nlohmann::json record(const PipelineRun& serial, const PipelineRun& pipelined, int engineThreads,
                      const RenderBenchSize& size) {
  const double frames = size.frames;
  auto perFrame = [&](double seconds) { return 1e3 * seconds / frames; };
  const double wallMs = perFrame(pipelined.times.wall);
  nlohmann::json out = benchRecord(engineThreads == 1 ? "render_end_to_end" : "render_end_to_end_engine_threads_all",
                                   pipelined.bodies, wallMs, "", 0);
  out["frames_per_second"] = 1e3 / wallMs;
  out["serial_frames_per_second"] = 1e3 / perFrame(serial.times.wall);
  out["engine_threads"] = engineThreads;
  // The serial run's stages, each alone on the machine.
  out["simulate_ms"] = perFrame(serial.simulateSeconds);
  out["emit_ms"] = perFrame(serial.emitSeconds);
  out["prepare_ms"] = perFrame(serial.times.prepare);
  out["draw_ms"] = perFrame(serial.times.draw);
  out["readback_ms"] = perFrame(serial.times.readBack);
  out["encode_ms"] = perFrame(serial.times.encode);
  out["write_ms"] = perFrame(serial.times.write);
  // CPU time per frame (every thread: the engine's, llvmpipe's, the encoders'),
  // which a loaded machine does not inflate the way it does wall times. With
  // perfect overlap on C cores a frame cannot take less than CPU / C.
  out["simulate_and_emit_cpu_ms"] = perFrame(serial.times.produceCpu);
  out["draw_and_readback_cpu_ms"] = perFrame(serial.times.renderCpu);
  out["encode_cpu_ms"] = perFrame(serial.times.encodeCpu);
  out["serial_cpu_ms"] = perFrame(serial.times.cpu);
  out["pipelined_cpu_ms"] = perFrame(pipelined.times.cpu);
  out["cores"] = cores();
  out["cpu_bound_frames_per_second"] = 1e3 * cores() / perFrame(serial.times.cpu);
  // The pipelined run: its wall time per frame and where the drawing thread waited.
  out["pipelined_wall_ms"] = wallMs;
  out["pipelined_simulate_ms"] = perFrame(pipelined.simulateSeconds);
  out["pipelined_draw_ms"] = perFrame(pipelined.times.prepare + pipelined.times.draw + pipelined.times.readBack);
  out["pipelined_encode_ms"] = perFrame(pipelined.times.encode + pipelined.times.write);
  out["wait_for_frame_ms"] = perFrame(pipelined.times.waitForFrame);
  out["wait_for_encoder_ms"] = perFrame(pipelined.times.waitForEncoder);
  out["bound_by"] = boundBy(pipelined.times);
  out["width"] = size.width;
  out["height"] = size.height;
  out["frames"] = size.frames;
  out["goal_frames_per_second"] = 60;
  return out;
}

void runRenderBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const RenderBenchSize size = benchSize(options.quick);
  render::Renderer renderer({size.width, size.height, 0});
  // One engine thread, then the machine's (0): on two cores the step's threads
  // compete with the pipeline's.
  for (const int engineThreads : options.quick ? std::vector<int>{1} : std::vector<int>{1, 0}) {
    const PipelineRun serial = runPipeline(size, engineThreads, viewer::PipelineMode::Serial, renderer);
    const PipelineRun pipelined = runPipeline(size, engineThreads, viewer::PipelineMode::Pipelined, renderer);
    sink(record(serial, pipelined, engineThreads, size));
  }
}

}  // namespace

Benchmark renderBenchmark() {
  return {"render",
          "frames per second end to end (simulate, draw, read back, PNG encode), ~1000 bodies, 1280x720, all layers; "
          "serial stage split and pipelined wall time",
          runRenderBenchmark};
}

}  // namespace physdbg::bench
