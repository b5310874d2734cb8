// physdbg bench render: frames per second end to end for a ~1000-body scene
// at 1280x720 with every 3D layer: simulate one step, emit and draw the
// frame, encode the PNG. Stages run one after another here, so the split
// shows which stage bounds a pipelined run (the CLI encodes on other cores).
// There is no peer: the record's peer fields are empty.
#include <chrono>
#include <filesystem>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "render/renderer.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::bench {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void runRenderBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int base = options.quick ? 8 : 44;  // 44 at the base: 990 boxes and a floor
  const int width = options.quick ? 320 : 1280, height = options.quick ? 180 : 720;
  const int frames = options.quick ? 3 : 60;
  World world = buildWorld(pyramidScene(base));
  const debugdraw::LayerSet layers = debugdraw::parseLayers("shapes,aabbs,fat,tree,contacts,velocities,pairs");
  render::Renderer renderer({width, height, 0});
  debugdraw::Frame framing;
  world.emitDebugDraw(debugdraw::parseLayers("shapes"), framing);
  const render::Camera camera = render::frameBoundsCamera(render::frameBounds(framing), double(width) / height);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("physdbg-render-bench-" + std::to_string(::getpid()) + ".png")).string();
  double simulateMs = 0, drawMs = 0, encodeMs = 0;
  for (int frame = 0; frame < frames; ++frame) {
    auto start = Clock::now();
    world.step();
    simulateMs += millisecondsSince(start);
    start = Clock::now();
    debugdraw::Frame primitives;
    world.emitDebugDraw(layers, primitives);
    const render::Image image = renderer.render(primitives, camera);
    drawMs += millisecondsSince(start);
    start = Clock::now();
    render::writePng(path, image);
    encodeMs += millisecondsSince(start);
  }
  std::filesystem::remove(path);
  const double frameMs = (simulateMs + drawMs + encodeMs) / frames;
  nlohmann::json record = benchRecord("render_end_to_end", static_cast<long long>(world.bodyCount()), frameMs, "", 0);
  record["frames_per_second"] = 1000.0 / frameMs;
  record["simulate_ms"] = simulateMs / frames;
  record["draw_ms"] = drawMs / frames;
  record["encode_ms"] = encodeMs / frames;
  // With encoding on the other core, the slower of the two sides sets the pace.
  record["pipelined_frames_per_second"] = 1000.0 / std::max((simulateMs + drawMs) / frames, encodeMs / frames);
  record["width"] = width;
  record["height"] = height;
  record["frames"] = frames;
  record["goal_frames_per_second"] = 60;
  sink(record);
}

}  // namespace

Benchmark renderBenchmark() {
  return {"render", "frames per second end to end (simulate, draw, PNG encode), ~1000 bodies, 1280x720, all layers",
          runRenderBenchmark};
}

}  // namespace physdbg::bench
