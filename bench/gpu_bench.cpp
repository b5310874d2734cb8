// physdbg bench gpu: the drop scenes (spheres, then boxes) with collision
// detection on the CPU and in compute shaders, side by side in one run on
// the same thread count; ratio = GPU / CPU per step. The GPU run's share
// spent uploading poses, dispatching and reading back is reported apart.
// On llvmpipe the "GPU" is the same CPU running the shaders through LLVM, so
// the figures measure correctness and overhead, not speed; on a machine with
// a GPU, `--backend egl` runs the same shaders there.
#include <algorithm>
#include <chrono>

#include <nlohmann/json.hpp>

#include "engine/world.h"
#include "bench/bench.h"
#include "bench/drop_scene.h"
#include "engine/parallel/task_system.h"
#include "gpu/gpu_collision.h"

namespace physdbg::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct CollisionRun {
  double msPerStep = 0.0;
  std::vector<Vec3> finalPositions;
  int leftContainer = 0;
  gpu::GpuCollisionTimings timings;
  std::string renderer;
};

CollisionRun runDrop(const DropScene& drop, int steps, const std::shared_ptr<gpu::GpuCollision>& stage) {
  SceneDescription scene = drop.scene;
  scene.world.collisionDevice = stage ? CollisionDevice::Gpu : CollisionDevice::Cpu;
  World world = buildWorld(scene, stage);
  const auto start = Clock::now();
  for (int step = 0; step < steps; ++step) world.step();
  CollisionRun run;
  run.msPerStep = 1e3 * std::chrono::duration<double>(Clock::now() - start).count() / steps;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const Vec3 position = world.body(static_cast<BodyId>(i)).position();
    run.finalPositions.push_back(position);
    if (static_cast<int>(i) >= drop.firstDropped && leftContainer(position, drop.container)) ++run.leftContainer;
  }
  if (stage) {
    run.timings = stage->timings();
    run.renderer = stage->identity().renderer;
  }
  return run;
}

double largestDifference(const CollisionRun& a, const CollisionRun& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.finalPositions.size(); ++i)
    largest = std::max(largest, (a.finalPositions[i] - b.finalPositions[i]).norm());
  return largest;
}

void runCase(int count, DropShape shape, int steps, const BenchOptions& options, const BenchSink& sink) {
  DropScene drop = dropScene(count, shape);
  const int threads = options.threads.value_or(0);
  drop.scene.world.threads = threads == 0 ? TaskSystem::hardwareThreads() : threads;
  const CollisionRun cpu = runDrop(drop, steps, nullptr);
  const auto stage = std::make_shared<gpu::GpuCollision>(render::parseBackend(options.backend));
  const CollisionRun gpu = runDrop(drop, steps, stage);
  nlohmann::json record = benchRecord(std::string("gpu/drop/") + (shape == DropShape::Sphere ? "spheres" : "boxes"),
                                      count, gpu.msPerStep, "physdbg, collision on the cpu", cpu.msPerStep);
  const double perStep = 1e3 / steps;
  record["threads"] = drop.scene.world.threads;
  record["steps"] = steps;
  record["backend"] = options.backend;
  record["renderer"] = gpu.renderer;
  record["upload_ms"] = perStep * gpu.timings.uploadSeconds;
  record["dispatch_ms"] = perStep * gpu.timings.dispatchSeconds;
  record["readback_ms"] = perStep * gpu.timings.readbackSeconds;
  record["dispatches_per_step"] = static_cast<double>(gpu.timings.dispatches) / steps;
  record["pairs_on_gpu_per_step"] = static_cast<double>(gpu.timings.pairsTested) / steps;
  record["cpu_left_container"] = cpu.leftContainer;
  record["gpu_left_container"] = gpu.leftContainer;
  // Contacts agree to round-off (tests/gpu/), but a pile is chaotic: the last
  // bits grow over the run. This says how far, not that either is wrong.
  record["largest_final_position_difference_m"] = largestDifference(cpu, gpu);
  if (gpu.renderer.find("llvmpipe") != std::string::npos)
    record["note"] = "llvmpipe runs the shaders on this CPU: correctness and overhead, not GPU speed";
  sink(record);
}

void runGpuBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const std::vector<int> counts = options.quick ? std::vector<int>{64} : std::vector<int>{1000, 4000, 16000};
  const int steps = options.quick ? 40 : 240;  // quick: long enough for the first layer to land
  for (const int count : counts)
    for (const DropShape shape : {DropShape::Sphere, DropShape::Box}) runCase(count, shape, steps, options, sink);
}

}  // namespace

Benchmark gpuBenchmark() {
  return {"gpu",
          "drop scenes with collision on the CPU and in compute shaders (GPU / CPU), upload, dispatch and readback "
          "times (N = 1000, 4000, 16000)",
          runGpuBenchmark};
}

}  // namespace physdbg::bench
