#include "bench/side_by_side.h"

#include <algorithm>
#include <chrono>
#include <malloc.h>
#include <nlohmann/json.hpp>

#include "engine/world.h"
#include "bench/bullet_world.h"
#include "bench/host_scaling.h"
#include "engine/parallel/task_system.h"

namespace physdbg::bench {
namespace {

template <typename Step>
double millisecondsPerStep(int steps, Step&& step) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) step();
  return 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
}

double heapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks + info.hblkhd);
}

}  // namespace

EngineRun runOurs(SceneDescription scene, int steps, const BenchOptions& options, int threads, bool warmUp) {
  if (options.solver) scene.world.solver.kind = *options.solver;
  scene.world.threads = threads;
  std::shared_ptr<CollisionOffload> offload;
  if (options.makeGpuCollision) {
    scene.world.collisionDevice = CollisionDevice::Gpu;
    offload = options.makeGpuCollision();
  }
  const double heapBefore = heapInUse();
  World world = buildWorld(scene, offload);
  EngineRun run;
  for (const RigidBody& body : world.bodies()) run.startPositions.push_back(body.position());
  if (warmUp) run.firstStepMs = millisecondsPerStep(1, [&] { world.step(); });
  run.msPerStep = millisecondsPerStep(steps, [&] {
    world.step();
    run.profile += world.lastStepStats().profile;
  });
  run.heapBytes = heapInUse() - heapBefore;
  for (const RigidBody& body : world.bodies()) {
    run.finalPositions.push_back(body.position());
    if (!body.isStatic()) run.kineticEnergy += body.kineticEnergy();
  }
  run.ran = true;
  return run;
}

EngineRun runBullet(const SceneDescription& scene, int steps, bool allowSleep, bool warmUp) {
  EngineRun run;
  if (!BulletWorld::available()) return run;
  const double heapBefore = heapInUse();
  BulletWorld world(scene, allowSleep);
  for (std::size_t i = 0; i < world.bodyCount(); ++i) run.startPositions.push_back(world.position(i));
  if (warmUp) run.firstStepMs = millisecondsPerStep(1, [&] { world.step(); });
  run.msPerStep = millisecondsPerStep(steps, [&] { world.step(); });
  run.heapBytes = heapInUse() - heapBefore;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) run.finalPositions.push_back(world.position(i));
  run.kineticEnergy = world.kineticEnergy();
  run.ran = true;
  return run;
}

std::vector<int> benchThreadCounts(const BenchOptions& options) {
  const int everyCore = TaskSystem::hardwareThreads();
  if (options.threads) return {*options.threads == 0 ? everyCore : *options.threads};
  return everyCore > 1 ? std::vector<int>{1, everyCore} : std::vector<int>{1};
}

void addStageFields(nlohmann::json& record, const EngineRun& ours, int steps) {
  nlohmann::json stages = nlohmann::json::object();
  for (const ProfileStage& stage : profileStages(ours.profile)) stages[stage.name] = 1e3 * stage.seconds / steps;
  record["ours_stage_ms"] = stages;
}

void addThreadFields(nlohmann::json& record, int threads, double msPerStep, std::optional<double> singleThreadMs) {
  record["threads"] = threads;
  if (threads > 1 && singleThreadMs && msPerStep > 0.0) record["scaling"] = *singleThreadMs / msPerStep;
  if (threads > 1) record["host_scaling"] = measureHostScaling(threads);  // taken just after the run
}

double largestDisplacement(const EngineRun& run) {
  double largest = 0.0;
  for (std::size_t i = 0; i < run.finalPositions.size(); ++i) {
    largest = std::max(largest, (run.finalPositions[i] - run.startPositions[i]).norm());
  }
  return largest;
}

}  // namespace physdbg::bench
