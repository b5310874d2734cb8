// Worlds whose collision runs in compute shaders (gpu/gpu_collision.h) on
// llvmpipe: stacks and pyramids stand as they do with the CPU path, the same
// run twice gives the same states, and a world asking for the gpu without a
// stage is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "gpu/gpu_collision.h"
#include "engine/world.h"
#include "scenes/scene.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::gpu {
namespace {

World gpuWorld(SceneDescription scene, std::shared_ptr<GpuCollision> stage = nullptr) {
  scene.world.collisionDevice = CollisionDevice::Gpu;
  return buildWorld(scene, stage ? stage : std::make_shared<GpuCollision>(render::Backend::OsMesa));
}

double largestDrift(const World& world, const SceneDescription& scene) {
  double largest = 0.0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    largest = std::max(largest, (world.body(static_cast<BodyId>(i)).position() - scene.bodies[i].position).norm());
  return largest;
}

TEST(GpuWorld, ATenBoxStackStandsAsWithTheCpuPath) {
  SceneDescription scene = stackScene(10);
  scene.world.allowSleep = false;
  World cpu = buildWorld(scene);
  World gpu = gpuWorld(scene);
  double deepest = 0.0;
  for (int step = 0; step < 600; ++step) {
    cpu.step();
    gpu.step();
    deepest = std::max(deepest, gpu.lastStepStats().largestPenetration);
  }
  EXPECT_LT(largestDrift(gpu, scene), 0.05);
  EXPECT_LT(deepest, 0.01);
  const BodyId top = static_cast<BodyId>(scene.bodies.size() - 1);
  EXPECT_LT((gpu.body(top).position() - cpu.body(top).position()).norm(), 0.01);
  EXPECT_GT(gpu.lastStepStats().narrowPhase.boxBox, 0) << "the box pairs were not answered as box-box";
}

TEST(GpuWorld, APyramidOfFiftyFiveBoxesStands) {
  const SceneDescription scene = pyramidScene(10);
  World world = gpuWorld(scene);
  for (int step = 0; step < 300; ++step) world.step();
  EXPECT_LT(largestDrift(world, scene), 0.05);
  EXPECT_LT(world.lastStepStats().largestPenetration, 0.01);
  EXPECT_TRUE(world.numericalFaults().empty());
}

TEST(GpuWorld, TheSameRunTwiceGivesTheSameStates) {
  const SceneDescription scene = resolveScene("default");
  World first = gpuWorld(scene), second = gpuWorld(scene);
  for (int step = 0; step < 120; ++step) {
    first.step();
    second.step();
  }
  for (std::size_t i = 0; i < first.bodyCount(); ++i) {
    const auto id = static_cast<BodyId>(i);
    EXPECT_EQ(first.body(id).position(), second.body(id).position()) << "body " << i;
    EXPECT_EQ(first.body(id).linearVelocity(), second.body(id).linearVelocity()) << "body " << i;
    EXPECT_EQ(first.body(id).angularVelocity(), second.body(id).angularVelocity()) << "body " << i;
  }
}

TEST(GpuWorld, TheCandidatePairsAreTheCpuTreesAtEveryStep) {
  SceneDescription scene = resolveScene("default");
  World cpu = buildWorld(scene);
  World gpu = gpuWorld(scene);
  for (int step = 0; step < 90; ++step) {
    cpu.step();
    gpu.step();
    // The states part slowly (float contacts); pairs must agree while they agree.
    if (step < 30) {
      ASSERT_EQ(gpu.candidatePairs(), cpu.candidatePairs()) << "step " << step;
    }
  }
}

// The GPU's broad phase with the CPU's narrow phase: the pairs are the
// tree's, so every built-in scene moves bit for bit as on the CPU, and its
// candidate pairs are equal at every step.
class GpuBroadPhaseOnly final : public CollisionOffload {
 public:
  std::unique_ptr<BroadPhase> makeBroadPhase(const DynamicAabbTreeOptions& options) override {
    return stage_.makeBroadPhase(options);
  }
  bool handles(ColliderKind, ColliderKind) const override { return false; }
  void collide(const std::vector<RigidBody>&, const std::vector<OffloadRequest>&,
               std::vector<OffloadedContact>&) override {}

 private:
  GpuCollision stage_{render::Backend::OsMesa};
};

void expectBitForBitWithTheGpuBroadPhase(SceneDescription scene, int steps) {
  World cpu = buildWorld(scene);
  scene.world.collisionDevice = CollisionDevice::Gpu;
  World gpu = buildWorld(scene, std::make_shared<GpuBroadPhaseOnly>());
  for (int step = 0; step < steps; ++step) {
    cpu.step();
    gpu.step();
    ASSERT_EQ(gpu.candidatePairs(), cpu.candidatePairs()) << scene.name << " step " << step;
  }
  for (std::size_t i = 0; i < cpu.bodyCount(); ++i)
    ASSERT_EQ(gpu.body(static_cast<BodyId>(i)).position(), cpu.body(static_cast<BodyId>(i)).position())
        << scene.name << " body " << i;
}

TEST(GpuWorld, EveryBuiltInSceneMovesBitForBitWithTheGpuBroadPhase) {
  for (const BuiltinScene& builtin : builtinScenes()) {
    const SceneDescription scene = builtin.make();
    if (scene.world.broadPhase != BroadPhaseKind::Tree) continue;  // brute force has no tree to match
    expectBitForBitWithTheGpuBroadPhase(scene, std::min(scene.steps, 240));
  }
}

// Bodies removed and added back (proxies freed and reused), and 512 mixed
// bodies with hulls, whose pairs the CPU narrow phase answers.
TEST(GpuWorld, ArrivalsAndAMixedPileMoveBitForBitWithTheGpuBroadPhase) {
  expectBitForBitWithTheGpuBroadPhase(loadSceneFile(PHYSDBG_SOURCE_DIR "/scenes/arrivals.json"), 240);
  expectBitForBitWithTheGpuBroadPhase(loadSceneFile(PHYSDBG_SOURCE_DIR "/scenes/mixed_pile.json"), 60);
}

TEST(GpuWorld, AWorldAskingForTheGpuWithoutAStageIsRefused) {
  WorldSettings settings;
  settings.collisionDevice = CollisionDevice::Gpu;
  EXPECT_THROW(World{settings}, std::invalid_argument);
  EXPECT_THROW((World{WorldSettings{}, std::make_shared<GpuCollision>(render::Backend::OsMesa)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::gpu
