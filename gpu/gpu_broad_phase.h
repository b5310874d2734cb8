#pragma once
// The broad phase with its pair search in compute shaders: a linear BVH
// (Morton codes, bitonic sort, Karras build) rebuilt on the GPU at every
// findPairs and traversed once per leaf. It answers exactly what
// TreeBroadPhase answers, so the two can be swapped and compared: fat boxes
// are kept on the CPU in doubles by the tree's own rule
// (engine/broadphase/fat_box.h), the GPU sees them as floats rounded outwards
// (so it can report too many pairs, never too few), and the CPU re-checks
// every candidate with the exact double test.
#include <cstdint>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/broadphase/tree_options.h"
#include "gpu/storage_buffer.h"
#include "render/gl_objects.h"

namespace physdbg::gpu {

class ComputeContext;

// Where the time of the last findPairs went, and how much crossed the bus.
// llvmpipe runs each dispatch as it is issued, so there the work shows in
// dispatchSeconds; a GPU queues them and the wait shows in readbackSeconds.
struct GpuBroadPhaseTimings {
  double uploadSeconds = 0, dispatchSeconds = 0, readbackSeconds = 0;
  int boxesUploaded = 0;
  int candidatePairs = 0;  // as the GPU reported them, before the exact re-check
};

class GpuBroadPhase final : public BroadPhase {
 public:
  // Of the options only margin and velocityPrediction apply: there is no tree.
  GpuBroadPhase(ComputeContext& context, const DynamicAabbTreeOptions& options);

  int addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) override;
  void removeProxy(int proxy) override;
  void moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) override;
  void setProxyActive(int proxy, bool active) override;
  void findPairs(std::vector<BodyPair>& pairs) override;
  const Aabb& fatBox(int proxy) const override;
  BroadPhaseStats stats() const override { return stats_; }

  const GpuBroadPhaseTimings& lastTimings() const { return timings_; }

 private:
  struct ProxyState {
    Aabb fatBox;
    std::uint32_t body = 0;
    ProxyMotion motion = ProxyMotion::Static;
    bool active = true;
    bool live = false;
    bool dirty = false;  // its GPU copy is stale
  };
  // What the shaders read of a proxy: std430 layout, two vec4. The fourth
  // float of the min holds the role (GpuRole), which decides eligibility on
  // the GPU too, so ineligible pairs never cost a slot in the pair list.
  struct GpuBox {
    float min[3];
    float role;
    float max[3];
    float padding;
  };

  struct MortonGrid {
    float origin[3];
    float scale[3];
  };

  void requireProxy(int proxy, const char* operation) const;
  void markDirty(int proxy);
  GpuBox toGpu(const ProxyState& state) const;
  MortonGrid mortonGrid() const;
  void uploadBoxes();
  void sortOnGpu(const MortonGrid& grid, std::uint32_t paddedCount);
  void buildTreeOnGpu();
  void searchPairsOnGpu();
  void readCandidates();
  void keepExactPairs(std::vector<BodyPair>& pairs) const;

  ComputeContext& context_;
  double margin_;
  double velocityPrediction_;
  std::vector<ProxyState> proxies_;  // indexed by proxy id
  std::vector<int> freeIds_;         // ids of removed proxies, reused last removed first
  std::vector<int> dirtyIds_;
  std::vector<GpuBox> uploadScratch_;
  std::vector<std::uint32_t> candidates_;  // pairs of proxy ids, as read back
  int liveCount_ = 0;
  std::uint32_t pairCapacity_ = 0;
  render::GlProgram keyProgram_, localSortProgram_, globalStepProgram_;
  render::GlProgram gatherProgram_, buildProgram_, boundsProgram_, traverseProgram_;
  StorageBuffer boxes_{"broad phase boxes"};
  StorageBuffer sortEntries_{"broad phase sort entries"};
  StorageBuffer sortedBoxes_{"broad phase sorted boxes"};
  StorageBuffer links_{"broad phase node links"};
  StorageBuffer nodeBoxes_{"broad phase node boxes"};
  StorageBuffer pairList_{"broad phase pair list"};
  std::size_t boxSlots_ = 0;  // slots the box buffer holds since it last grew
  GpuBroadPhaseTimings timings_;
  BroadPhaseStats stats_;
  long long reinsertedSinceFind_ = 0;
};

}  // namespace physdbg::gpu
