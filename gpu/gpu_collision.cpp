#include "gpu/gpu_collision.h"

#include <utility>

#include "gpu/gpu_broad_phase.h"
#include "gpu/gpu_narrow_phase.h"

namespace physdbg::gpu {
namespace {

// The world owns its broad phase and may destroy it while another context
// (the renderer's) is current: making ours current first keeps the buffer
// names deleted ours. It also sums each findPairs' times for the bench.
class OwnedBroadPhase final : public BroadPhase {
 public:
  OwnedBroadPhase(ComputeContext& context, const DynamicAabbTreeOptions& options,
                  std::shared_ptr<GpuCollisionTimings> sums)
      : context_(context), inner_(std::make_unique<GpuBroadPhase>(context, options)), sums_(std::move(sums)) {}
  ~OwnedBroadPhase() override {
    context_.tryMakeCurrent();
    inner_.reset();
  }
  OwnedBroadPhase(const OwnedBroadPhase&) = delete;
  OwnedBroadPhase& operator=(const OwnedBroadPhase&) = delete;

  int addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) override {
    return inner_->addProxy(tightBox, body, motion);
  }
  void removeProxy(int proxy) override { inner_->removeProxy(proxy); }
  void moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) override {
    inner_->moveProxy(proxy, tightBox, displacement);
  }
  void setProxyActive(int proxy, bool active) override { inner_->setProxyActive(proxy, active); }
  void findPairs(std::vector<BodyPair>& pairs) override {
    inner_->findPairs(pairs);
    const GpuBroadPhaseTimings& last = inner_->lastTimings();
    sums_->uploadSeconds += last.uploadSeconds;
    sums_->dispatchSeconds += last.dispatchSeconds;
    sums_->readbackSeconds += last.readbackSeconds;
    ++sums_->dispatches;
  }
  const Aabb& fatBox(int proxy) const override { return inner_->fatBox(proxy); }
  BroadPhaseStats stats() const override { return inner_->stats(); }

 private:
  ComputeContext& context_;
  std::unique_ptr<GpuBroadPhase> inner_;
  std::shared_ptr<GpuCollisionTimings> sums_;
};

}  // namespace

GpuCollision::GpuCollision(render::Backend backend)
    : context_(std::make_unique<ComputeContext>(backend)),
      narrowPhase_(std::make_unique<GpuNarrowPhase>(*context_)),
      broadTimings_(std::make_shared<GpuCollisionTimings>()) {}

GpuCollision::~GpuCollision() {
  context_->tryMakeCurrent();
  narrowPhase_.reset();
}

std::unique_ptr<BroadPhase> GpuCollision::makeBroadPhase(const DynamicAabbTreeOptions& options) {
  return std::make_unique<OwnedBroadPhase>(*context_, options, broadTimings_);
}

bool GpuCollision::handles(ColliderKind a, ColliderKind b) const { return GpuNarrowPhase::supports(a, b); }

void GpuCollision::collide(const std::vector<RigidBody>& bodies, const std::vector<OffloadRequest>& requests,
                           std::vector<OffloadedContact>& out) {
  narrowPhase_->collide(bodies, requests, out);
  const GpuNarrowPhaseTimings& last = narrowPhase_->lastTimings();
  narrowTimings_.uploadSeconds += last.uploadSeconds;
  narrowTimings_.dispatchSeconds += last.dispatchSeconds;
  narrowTimings_.readbackSeconds += last.readbackSeconds;
  ++narrowTimings_.dispatches;
  narrowTimings_.pairsTested += static_cast<long long>(requests.size()) - last.cpuFallbacks;
}

GpuCollisionTimings GpuCollision::timings() const {
  GpuCollisionTimings sum = narrowTimings_;
  sum.uploadSeconds += broadTimings_->uploadSeconds;
  sum.dispatchSeconds += broadTimings_->dispatchSeconds;
  sum.readbackSeconds += broadTimings_->readbackSeconds;
  sum.dispatches += broadTimings_->dispatches;
  return sum;
}

}  // namespace physdbg::gpu
