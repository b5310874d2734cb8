#include "bench/side_by_side.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
  run.contacts = static_cast<int>(world.touchingPairCount());  // sleeping pairs too: a pyramid asleep still stands on them
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
  // Within physdbg's touching gap (SolverSettings::linearSlop), as it counts.
  run.contacts = world.touchingPairs(scene.world.solver.linearSlop);
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

namespace {

struct WorkSummary {
  double meanHeight = 0.0;
  int outside = 0;
};

WorkSummary summarise(const EngineRun& run, const WorkCheck& check) {
  WorkSummary summary;
  std::size_t counted = 0;
  for (std::size_t i = check.firstDynamic; i < run.finalPositions.size(); ++i) {
    summary.meanHeight += run.finalPositions[i].y();
    ++counted;
    if (check.outside && check.outside(run.finalPositions[i])) ++summary.outside;
  }
  if (counted > 0) summary.meanHeight /= static_cast<double>(counted);
  return summary;
}

}  // namespace

void addWorkFields(nlohmann::json& record, const EngineRun& ours, const EngineRun& peer, const WorkCheck& check) {
  const WorkSummary mine = summarise(ours, check);
  record["ours_contacts"] = ours.contacts;
  record["ours_mean_height"] = mine.meanHeight;
  record["ours_outside"] = mine.outside;
  if (!peer.ran) {
    record["same_work"] = nullptr;
    return;
  }
  const WorkSummary theirs = summarise(peer, check);
  record["peer_contacts"] = peer.contacts;
  record["peer_mean_height"] = theirs.meanHeight;
  record["peer_outside"] = theirs.outside;
  const double contactGap = std::abs(ours.contacts - peer.contacts);
  record["same_work"] = contactGap <= 0.2 * std::max(ours.contacts, peer.contacts) &&
                        std::abs(mine.meanHeight - theirs.meanHeight) <= 0.05 * check.bodySize &&
                        mine.outside == 0 && theirs.outside == 0;
}

double largestDisplacement(const EngineRun& run) {
  double largest = 0.0;
  for (std::size_t i = 0; i < run.finalPositions.size(); ++i) {
    largest = std::max(largest, (run.finalPositions[i] - run.startPositions[i]).norm());
  }
  return largest;
}

}  // namespace physdbg::bench
