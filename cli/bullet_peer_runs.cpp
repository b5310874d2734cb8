#include "cli/bullet_peer_runs.h"

#include <algorithm>
#include <chrono>

#include "bench/bullet_world.h"

namespace physdbg::cli {
namespace {

reports::SolverMeasure measureBullet(const SceneDescription& scene, int iterations, int steps) {
  bench::BulletWorld world(scene, false);
  world.setSolverIterations(iterations);
  std::vector<Vec3> start;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) start.push_back(world.position(i));
  reports::SolverMeasure measure;
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    world.step();
    measure.largestPenetration = std::max(measure.largestPenetration, world.largestPenetration());
  }
  measure.msPerStep = 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() / steps;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    measure.drift = std::max(measure.drift, (world.position(i) - start[i]).norm());
  }
  return measure;
}

class BulletSimulation final : public reports::ReferenceSimulation {
 public:
  explicit BulletSimulation(const SceneDescription& scene) : world_(scene, false) {}
  void step() override { world_.step(); }
  Vec3 position(std::size_t body) const override { return world_.position(body); }
  Vec3 linearVelocity(std::size_t body) const override { return world_.linearVelocity(body); }

 private:
  bench::BulletWorld world_;
};

}  // namespace

reports::SimulationFactory bulletSimulation() {
  if (!bench::BulletWorld::available()) return {};
  return [](const SceneDescription& scene) -> std::unique_ptr<reports::ReferenceSimulation> {
    return std::make_unique<BulletSimulation>(scene);
  };
}

reports::PeerSolverRun bulletSolverRun() {
  if (!bench::BulletWorld::available()) return {};
  return measureBullet;
}

}  // namespace physdbg::cli
