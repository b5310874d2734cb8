#include "gpu/gpu_broad_phase.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/broadphase/fat_box.h"
#include "gpu/broad_phase_shaders.h"
#include "gpu/compute_context.h"
#include "render/gl_headers.h"

namespace physdbg::gpu {
namespace {

// Roles as the shaders read them from a box's min.w.
constexpr float roleNone = 0.0f, rolePassive = 1.0f, roleDrives = 2.0f;
constexpr std::size_t pairListHeaderBytes = 2 * sizeof(std::uint32_t);
constexpr std::size_t pairBytes = 2 * sizeof(std::uint32_t);
constexpr std::size_t sortEntryBytes = 2 * sizeof(std::uint32_t);
constexpr std::size_t linkBytes = 4 * sizeof(std::uint32_t);

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The float at or below value (roundUp false) or at or above it, so a float
// box always contains the double box it stands for. Beyond the float range
// the bound becomes infinite, and the clamp keeps the conversion defined.
float roundOutwards(double value, bool roundUp) {
  constexpr double largest = std::numeric_limits<float>::max();
  constexpr float infinity = std::numeric_limits<float>::infinity();
  if (value > largest) return roundUp ? infinity : std::numeric_limits<float>::max();
  if (value < -largest) return roundUp ? -std::numeric_limits<float>::max() : -infinity;
  const float nearest = static_cast<float>(value);
  if (roundUp && static_cast<double>(nearest) < value) return std::nextafter(nearest, infinity);
  if (!roundUp && static_cast<double>(nearest) > value) return std::nextafter(nearest, -infinity);
  return nearest;
}

void setUniform(const render::GlProgram& program, const char* name, std::uint32_t value) {
  glUniform1ui(glGetUniformLocation(program.get(), name), value);
}

void dispatch(std::uint32_t groups) {
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

render::GlProgram compileShader(const char* body, const char* label) {
  return render::createComputeProgram(broadPhaseProgramSource(body).c_str(), label);
}

std::uint32_t groupsFor(std::uint32_t threads) { return (threads + broadPhaseGroupSize - 1) / broadPhaseGroupSize; }

}  // namespace

GpuBroadPhase::GpuBroadPhase(ComputeContext& context, const DynamicAabbTreeOptions& options)
    : context_(context), margin_(options.margin), velocityPrediction_(options.velocityPrediction) {
  if (!(margin_ >= 0.0) || !std::isfinite(margin_)) {
    throw std::invalid_argument("GpuBroadPhase: margin must be finite and >= 0");
  }
  if (!(velocityPrediction_ >= 0.0) || !std::isfinite(velocityPrediction_)) {
    throw std::invalid_argument("GpuBroadPhase: velocityPrediction must be finite and >= 0");
  }
  context_.makeCurrent();
  keyProgram_ = compileShader(broadPhaseKeyShader, "broad phase keys");
  localSortProgram_ = compileShader(broadPhaseLocalSortShader, "broad phase local sort");
  globalStepProgram_ = compileShader(broadPhaseGlobalStepShader, "broad phase global step");
  gatherProgram_ = compileShader(broadPhaseGatherShader, "broad phase gather");
  buildProgram_ = compileShader(broadPhaseBuildShader, "broad phase build");
  boundsProgram_ = compileShader(broadPhaseBoundsShader, "broad phase bounds");
  traverseProgram_ = compileShader(broadPhaseTraverseShader, "broad phase traverse");
}

void GpuBroadPhase::requireProxy(int proxy, const char* operation) const {
  if (proxy < 0 || proxy >= static_cast<int>(proxies_.size()) || !proxies_[proxy].live) {
    throw std::invalid_argument(std::string("GpuBroadPhase::") + operation + ": " + std::to_string(proxy) +
                                " is not a live proxy");
  }
}

void GpuBroadPhase::markDirty(int proxy) {
  if (proxies_[proxy].dirty) return;
  proxies_[proxy].dirty = true;
  dirtyIds_.push_back(proxy);
}

int GpuBroadPhase::addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) {
  if (!tightBox.isValid()) throw std::invalid_argument("GpuBroadPhase::addProxy: box must be finite with min <= max");
  int proxy = static_cast<int>(proxies_.size());
  if (freeIds_.empty()) {
    proxies_.emplace_back();
  } else {
    proxy = freeIds_.back();
    freeIds_.pop_back();
  }
  ProxyState& state = proxies_[proxy];
  state.fatBox = fattenBox(tightBox, Vec3::Zero(), margin_, velocityPrediction_);
  state.body = body;
  state.motion = motion;
  state.active = true;
  state.live = true;
  ++liveCount_;
  markDirty(proxy);
  return proxy;
}

void GpuBroadPhase::removeProxy(int proxy) {
  requireProxy(proxy, "removeProxy");
  proxies_[proxy].live = false;
  --liveCount_;
  freeIds_.push_back(proxy);
  markDirty(proxy);
}

void GpuBroadPhase::moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) {
  requireProxy(proxy, "moveProxy");
  if (!tightBox.isValid()) throw std::invalid_argument("GpuBroadPhase::moveProxy: box must be finite with min <= max");
  if (!displacement.allFinite()) throw std::invalid_argument("GpuBroadPhase::moveProxy: displacement not finite");
  ProxyState& state = proxies_[proxy];
  if (state.fatBox.contains(tightBox)) return;
  state.fatBox = fattenBox(tightBox, displacement, margin_, velocityPrediction_);
  ++reinsertedSinceFind_;
  markDirty(proxy);
}

void GpuBroadPhase::setProxyActive(int proxy, bool active) {
  requireProxy(proxy, "setProxyActive");
  if (proxies_[proxy].active == active) return;
  proxies_[proxy].active = active;
  markDirty(proxy);  // its role changes
}

const Aabb& GpuBroadPhase::fatBox(int proxy) const {
  requireProxy(proxy, "fatBox");
  return proxies_[proxy].fatBox;
}

GpuBroadPhase::GpuBox GpuBroadPhase::toGpu(const ProxyState& state) const {
  GpuBox box{};
  for (int axis = 0; axis < 3; ++axis) {
    box.min[axis] = roundOutwards(state.fatBox.min[axis], false);
    box.max[axis] = roundOutwards(state.fatBox.max[axis], true);
  }
  const bool drives = state.motion == ProxyMotion::Dynamic && state.active;
  box.role = !state.live ? roleNone : drives ? roleDrives : rolePassive;
  return box;
}

// The grid the Morton codes quantise the box centres to: the centres'
// bounds in 1024 cells a side. Any grid gives the right pairs; a tight one
// gives a better tree.
GpuBroadPhase::MortonGrid GpuBroadPhase::mortonGrid() const {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const ProxyState& state : proxies_) {
    if (!state.live) continue;
    low = low.cwiseMin(state.fatBox.center());
    high = high.cwiseMax(state.fatBox.center());
  }
  const Vec3 scale = (high - low).cwiseMax(Vec3::Constant(1e-30)).cwiseInverse() * 1023.0;
  MortonGrid grid;
  for (int axis = 0; axis < 3; ++axis) {
    grid.origin[axis] = static_cast<float>(low[axis]);
    grid.scale[axis] = static_cast<float>(std::min(scale[axis], 1e30));
  }
  return grid;
}

// Uploads the boxes that changed since the last call, in runs of adjacent
// slots; all of them when the buffer had to grow (growing drops its contents).
void GpuBroadPhase::uploadBoxes() {
  const std::size_t slots = proxies_.size();
  if (slots > boxSlots_) {
    boxes_.reserve(slots * sizeof(GpuBox));
    boxSlots_ = boxes_.capacity() / sizeof(GpuBox);
    dirtyIds_.clear();
    for (std::size_t proxy = 0; proxy < slots; ++proxy) dirtyIds_.push_back(static_cast<int>(proxy));
  }
  std::sort(dirtyIds_.begin(), dirtyIds_.end());
  std::size_t begin = 0;
  while (begin < dirtyIds_.size()) {
    std::size_t end = begin + 1;
    while (end < dirtyIds_.size() && dirtyIds_[end] == dirtyIds_[end - 1] + 1) ++end;
    uploadScratch_.clear();
    for (std::size_t index = begin; index < end; ++index) {
      ProxyState& state = proxies_[dirtyIds_[index]];
      uploadScratch_.push_back(toGpu(state));
      state.dirty = false;
    }
    boxes_.upload(static_cast<std::size_t>(dirtyIds_[begin]) * sizeof(GpuBox), uploadScratch_.data(),
                  uploadScratch_.size() * sizeof(GpuBox));
    begin = end;
  }
  timings_.boxesUploaded = static_cast<int>(dirtyIds_.size());
  dirtyIds_.clear();
}

// Keys, then a bitonic sort: one dispatch sorts every block in shared memory;
// each later stage takes one dispatch per step whose partners lie in
// different blocks and one that finishes the stage within the blocks.
void GpuBroadPhase::sortOnGpu(const MortonGrid& grid, std::uint32_t paddedCount) {
  sortEntries_.reserve(static_cast<std::size_t>(paddedCount) * sortEntryBytes);
  boxes_.bind(0);
  sortEntries_.bind(1);
  glUseProgram(keyProgram_.get());
  setUniform(keyProgram_, "slotCount", static_cast<std::uint32_t>(proxies_.size()));
  setUniform(keyProgram_, "paddedCount", paddedCount);
  glUniform3fv(glGetUniformLocation(keyProgram_.get(), "origin"), 1, grid.origin);
  glUniform3fv(glGetUniformLocation(keyProgram_.get(), "scale"), 1, grid.scale);
  dispatch(groupsFor(paddedCount));
  const std::uint32_t blocks = paddedCount / broadPhaseSortBlock;
  glUseProgram(localSortProgram_.get());
  setUniform(localSortProgram_, "mergeStage", 0);
  dispatch(blocks);
  for (std::uint32_t stage = 2 * broadPhaseSortBlock; stage <= paddedCount; stage *= 2) {
    glUseProgram(globalStepProgram_.get());
    setUniform(globalStepProgram_, "stage", stage);
    for (std::uint32_t step = stage / 2; step >= broadPhaseSortBlock; step /= 2) {
      setUniform(globalStepProgram_, "step", step);
      dispatch(groupsFor(paddedCount / 2));
    }
    glUseProgram(localSortProgram_.get());
    setUniform(localSortProgram_, "mergeStage", stage);
    dispatch(blocks);
  }
}

// Leaves in sort order, the internal nodes' links, then their boxes.
void GpuBroadPhase::buildTreeOnGpu() {
  const auto live = static_cast<std::uint32_t>(liveCount_);
  sortedBoxes_.reserve(live * sizeof(GpuBox));
  links_.reserve(live * linkBytes);
  nodeBoxes_.reserve(live * sizeof(GpuBox));
  boxes_.bind(0);
  sortEntries_.bind(1);
  sortedBoxes_.bind(3);
  links_.bind(4);
  nodeBoxes_.bind(5);
  glUseProgram(gatherProgram_.get());
  setUniform(gatherProgram_, "liveCount", live);
  dispatch(groupsFor(live));
  glUseProgram(buildProgram_.get());
  glUniform1i(glGetUniformLocation(buildProgram_.get(), "liveCount"), liveCount_);
  dispatch(groupsFor(live - 1));
  glUseProgram(boundsProgram_.get());
  setUniform(boundsProgram_, "liveCount", live);
  dispatch(groupsFor(live - 1));
}

void GpuBroadPhase::searchPairsOnGpu() {
  pairList_.reserve(pairListHeaderBytes + static_cast<std::size_t>(pairCapacity_) * pairBytes);
  const std::uint32_t zero[2] = {0, 0};
  pairList_.upload(0, zero, sizeof(zero));
  sortEntries_.bind(1);
  pairList_.bind(2);
  sortedBoxes_.bind(3);
  links_.bind(4);
  nodeBoxes_.bind(5);
  glUseProgram(traverseProgram_.get());
  setUniform(traverseProgram_, "liveCount", static_cast<std::uint32_t>(liveCount_));
  setUniform(traverseProgram_, "capacity", pairCapacity_);
  dispatch(groupsFor(static_cast<std::uint32_t>(liveCount_)));
}

// One download of the count and as many pairs as the last call had (plus
// room); a second one only for the rest of a list that grew. A list that
// overflowed the buffer is counted all the same, so one re-dispatch with
// room for that count suffices.
void GpuBroadPhase::readCandidates() {
  for (int attempt = 0; attempt < 2; ++attempt) {
    const std::uint32_t expected =
        std::min<std::uint32_t>(pairCapacity_, static_cast<std::uint32_t>(timings_.candidatePairs) / 4 * 5 + 256);
    candidates_.resize(2 + 2 * static_cast<std::size_t>(expected));
    pairList_.download(0, candidates_.data(), candidates_.size() * sizeof(std::uint32_t));
    const std::uint32_t count = candidates_[0];
    if (count <= pairCapacity_) {
      candidates_.resize(2 + 2 * static_cast<std::size_t>(count));
      if (count > expected) {
        pairList_.download(pairListHeaderBytes + expected * pairBytes, candidates_.data() + 2 + 2 * expected,
                           (count - expected) * pairBytes);
      }
      timings_.candidatePairs = static_cast<int>(count);
      return;
    }
    pairCapacity_ = count / 4 * 5 + 256;
    searchPairsOnGpu();
  }
  throw std::logic_error("GpuBroadPhase: the pair list overflowed twice");
}

// The GPU's pairs are a superset (float boxes rounded outwards); the exact
// double test and the eligibility rule make them the tree's pairs.
void GpuBroadPhase::keepExactPairs(std::vector<BodyPair>& pairs) const {
  pairs.clear();
  const auto drives = [](const ProxyState& state) { return state.motion == ProxyMotion::Dynamic && state.active; };
  for (std::size_t index = 2; index + 1 < candidates_.size(); index += 2) {
    const ProxyState& first = proxies_[candidates_[index]];
    const ProxyState& second = proxies_[candidates_[index + 1]];
    if (!first.live || !second.live || first.body == second.body) continue;
    if (!drives(first) && !drives(second)) continue;
    if (!overlapping(first.fatBox, second.fatBox)) continue;
    pairs.push_back({std::min(first.body, second.body), std::max(first.body, second.body)});
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

void GpuBroadPhase::findPairs(std::vector<BodyPair>& pairs) {
  const int previousCandidates = timings_.candidatePairs;
  timings_ = GpuBroadPhaseTimings{};
  timings_.candidatePairs = previousCandidates;  // sizes this call's first download
  stats_ = BroadPhaseStats{};
  stats_.proxiesReinserted = reinsertedSinceFind_;
  reinsertedSinceFind_ = 0;
  pairs.clear();
  candidates_.clear();
  if (liveCount_ < 2) {
    timings_.candidatePairs = 0;
    return;  // the changed boxes wait for a call that searches
  }
  context_.makeCurrent();
  auto start = std::chrono::steady_clock::now();
  uploadBoxes();
  timings_.uploadSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  const MortonGrid grid = mortonGrid();
  const auto paddedCount = std::max(broadPhaseSortBlock, std::bit_ceil(static_cast<std::uint32_t>(proxies_.size())));
  pairCapacity_ = std::max<std::uint32_t>(pairCapacity_, 4 * static_cast<std::uint32_t>(liveCount_) + 1024);
  sortOnGpu(grid, paddedCount);
  buildTreeOnGpu();
  searchPairsOnGpu();
  timings_.dispatchSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  readCandidates();
  timings_.readbackSeconds = secondsSince(start);
  keepExactPairs(pairs);
  stats_.boxesTested = timings_.candidatePairs;
}

}  // namespace physdbg::gpu
