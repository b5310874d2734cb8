#include "cli/collision_device.h"

#include "cli/arguments.h"
#include "gpu/gpu_collision.h"

namespace physdbg::cli {

std::shared_ptr<CollisionOffload> collisionOffloadFor(const SceneDescription& scene, render::Backend backend) {
  if (scene.world.collisionDevice != CollisionDevice::Gpu) return nullptr;
  try {
    return std::make_shared<gpu::GpuCollision>(backend);
  } catch (const gpu::ComputeUnavailable& error) {
    throw UsageError(std::string("collision on the gpu: ") + error.what());
  }
}

}  // namespace physdbg::cli
