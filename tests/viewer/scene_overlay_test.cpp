// The overlay's first line names the collision device when it is the GPU, so
// a frame from the compute-shader path never passes for a CPU one.
#include "engine/world.h"
#include "viewer/scene_overlay.h"

#include <gtest/gtest.h>

#include <memory>

#include "gpu/gpu_collision.h"
#include "scenes/scene.h"

namespace physdbg::viewer {
namespace {

std::string firstLine(const SceneDescription& scene, const World& world) {
  debugdraw::Frame frame;
  addOverlay(scene, world, OverlayCounters{}, frame);
  return frame.texts.at(0).text;
}

TEST(SceneOverlay, NamesTheGpuWhenCollisionRunsThere) {
  SceneDescription scene = resolveScene("stack");
  const World cpu = buildWorld(scene);
  EXPECT_EQ(firstLine(scene, cpu).find("gpu"), std::string::npos) << firstLine(scene, cpu);
  scene.world.collisionDevice = CollisionDevice::Gpu;
  const World gpu = buildWorld(scene, std::make_shared<gpu::GpuCollision>(render::Backend::OsMesa));
  EXPECT_NE(firstLine(scene, gpu).find("collision on the gpu"), std::string::npos) << firstLine(scene, gpu);
}

}  // namespace
}  // namespace physdbg::viewer
