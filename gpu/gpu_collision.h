#pragma once
// The compute-shader collision stage as the World sees it (CollisionOffload):
// the broad phase's pair search and the narrow phase of sphere, box and
// capsule pairs run on the context's device; convex meshes and the pairs
// without a shader stay on the CPU in the same step. One GpuCollision per
// World: its buffers hold that world's bodies between steps.
#include <memory>

#include "engine/collision_offload.h"
#include "gpu/compute_context.h"

namespace physdbg::gpu {

class GpuBroadPhase;
class GpuNarrowPhase;

// Seconds summed over every call since the stage was made, so a bench can
// divide by its steps.
struct GpuCollisionTimings {
  double uploadSeconds = 0, dispatchSeconds = 0, readbackSeconds = 0;
  long long dispatches = 0;   // findPairs and narrow-phase batches that reached the device
  long long pairsTested = 0;  // narrow-phase pairs answered on the device
};

class GpuCollision final : public CollisionOffload {
 public:
  // Throws ComputeUnavailable naming what is missing (compute_context.h).
  explicit GpuCollision(render::Backend backend);
  ~GpuCollision() override;

  std::unique_ptr<BroadPhase> makeBroadPhase(const DynamicAabbTreeOptions& options) override;
  bool handles(ColliderKind a, ColliderKind b) const override;
  void collide(const std::vector<RigidBody>& bodies, const std::vector<OffloadRequest>& requests,
               std::vector<OffloadedContact>& out) override;

  const ComputeIdentity& identity() const { return context_->identity(); }
  // The narrow phase's sums and, when the world's broad phase is this
  // stage's, its findPairs sums too.
  GpuCollisionTimings timings() const;

 private:
  std::unique_ptr<ComputeContext> context_;
  std::unique_ptr<GpuNarrowPhase> narrowPhase_;
  GpuCollisionTimings narrowTimings_;
  // Shared with the broad phase the world owns, which adds its own sums
  // here; it may outlive neither this object nor its context.
  std::shared_ptr<GpuCollisionTimings> broadTimings_;
};

}  // namespace physdbg::gpu
