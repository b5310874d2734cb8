// The GPU broad phase against the tree on llvmpipe: the same calls on both,
// and after every findPairs the same pairs and the same fat boxes.
#include "gpu/gpu_broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "engine/broadphase/tree_broad_phase.h"
#include "gpu/compute_context.h"

namespace physdbg::gpu {
namespace {

// One context for the whole suite: making one costs more than a scene.
ComputeContext& sharedContext() {
  static ComputeContext context(render::Backend::OsMesa);
  return context;
}

enum class SceneKind { Scattered, Touching, Identical, MixedSizes, FarAway };

struct SceneSpec {
  unsigned seed = 0;
  int proxies = 0;
  SceneKind kind = SceneKind::Scattered;
  DynamicAabbTreeOptions options;
};

// A proxy as the test sees it: the ids each broad phase gave it, and the
// tight box the moves start from.
struct Handle {
  int treeProxy = -1, gpuProxy = -1;
  Aabb tight;
  bool dynamic = true;
  bool active = true;
};

struct Tally {
  long long findPairsCalls = 0;
  long long pairsCompared = 0;
  long long mismatches = 0;
};

// Touching scenes put boxes on a dyadic lattice whose fat boxes meet exactly
// (in doubles); identical scenes stack copies of a few boxes; far-away ones
// sit ~1e4 m out, where a float step is about a millimetre.
Aabb sceneBox(const SceneSpec& spec, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double world = 2.0 * std::cbrt(static_cast<double>(spec.proxies)) + 2.0;
  const auto scattered = [&](double half) {
    const Vec3 center(world * unit(random), world * unit(random), world * unit(random));
    return Aabb::fromCenterHalfExtents(center, Vec3::Constant(half));
  };
  switch (spec.kind) {
    case SceneKind::Touching: {
      std::uniform_int_distribution<int> cell(0, static_cast<int>(world));
      const double pitch = 0.5 + 2.0 * spec.options.margin;
      const Vec3 corner = Vec3(cell(random), cell(random), cell(random)) * pitch;
      return {corner, corner + Vec3::Constant(0.5)};
    }
    case SceneKind::Identical: {
      std::uniform_int_distribution<int> pick(0, 3);
      const Vec3 corner = Vec3::Constant(0.25 * pick(random));
      return {corner, corner + Vec3::Constant(0.5)};
    }
    case SceneKind::MixedSizes: {
      const double draw = unit(random);
      if (draw < 0.02) return scattered(0.25 * world);  // huge
      if (draw < 0.3) return scattered(1e-5);           // tiny
      return scattered(0.05 + 0.4 * unit(random));
    }
    case SceneKind::FarAway: {
      Aabb box = scattered(0.05 + 0.4 * unit(random));
      const Vec3 offset(1e4, -1e4, 1.25e4);
      return {box.min + offset, box.max + offset};
    }
    case SceneKind::Scattered:
      break;
  }
  return scattered(0.05 + 0.4 * unit(random));
}

class Comparison {
 public:
  explicit Comparison(const SceneSpec& spec)
      : spec_(spec), random_(spec.seed), tree_(spec.options), gpu_(sharedContext(), spec.options) {}

  void run(int steps, Tally& tally) {
    for (int index = 0; index < spec_.proxies; ++index) add();
    compare(tally);
    for (int step = 0; step < steps; ++step) {
      this->step();
      compare(tally);
    }
  }

 private:
  void add() {
    Handle handle;
    handle.tight = sceneBox(spec_, random_);
    handle.dynamic = std::bernoulli_distribution(0.7)(random_);
    const ProxyMotion motion = handle.dynamic ? ProxyMotion::Dynamic : ProxyMotion::Static;
    // A few bodies own two proxies: they make one pair, never one with themselves.
    std::uint32_t body = nextBody_++;
    if (!handles_.empty() && std::bernoulli_distribution(0.05)(random_)) body = body / 2;
    handle.treeProxy = tree_.addProxy(handle.tight, body, motion);
    handle.gpuProxy = gpu_.addProxy(handle.tight, body, motion);
    handles_.push_back(handle);
  }

  void remove(std::size_t index) {
    tree_.removeProxy(handles_[index].treeProxy);
    gpu_.removeProxy(handles_[index].gpuProxy);
    handles_[index] = handles_.back();
    handles_.pop_back();
  }

  // Touching and identical scenes move by dyadic steps, so that boxes keep
  // meeting exactly; the others by any amount, now and then a long jump.
  Vec3 displacement() {
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    if (spec_.kind == SceneKind::Touching || spec_.kind == SceneKind::Identical) {
      std::uniform_int_distribution<int> steps(-2, 2);
      return Vec3(steps(random_), steps(random_), steps(random_)) * 0.0625;
    }
    Vec3 move(small(random_), small(random_), small(random_));
    if (std::bernoulli_distribution(0.02)(random_)) move *= 40.0;
    return move;
  }

  void step() {
    std::bernoulli_distribution moves(0.6), toggles(0.03), removes(0.01), adds(0.02);
    for (std::size_t index = 0; index < handles_.size(); ++index) {
      Handle& handle = handles_[index];
      if (handle.dynamic && handle.active && moves(random_)) {
        const Vec3 move = displacement();
        handle.tight = Aabb{handle.tight.min + move, handle.tight.max + move};
        tree_.moveProxy(handle.treeProxy, handle.tight, move);
        gpu_.moveProxy(handle.gpuProxy, handle.tight, move);
      }
      if (toggles(random_)) {
        handle.active = !handle.active;
        tree_.setProxyActive(handle.treeProxy, handle.active);
        gpu_.setProxyActive(handle.gpuProxy, handle.active);
      }
    }
    for (std::size_t index = handles_.size(); index-- > 0;) {
      if (removes(random_)) remove(index);
    }
    if (adds(random_) || handles_.size() < 2) add();
  }

  void compare(Tally& tally) {
    tree_.findPairs(treePairs_);
    gpu_.findPairs(gpuPairs_);
    ++tally.findPairsCalls;
    tally.pairsCompared += static_cast<long long>(treePairs_.size());
    if (treePairs_ != gpuPairs_) {
      ++tally.mismatches;
      ADD_FAILURE() << "seed " << spec_.seed << ": tree " << treePairs_.size() << " pairs, GPU " << gpuPairs_.size();
    }
    for (const Handle& handle : handles_) {
      const Aabb& expected = tree_.fatBox(handle.treeProxy);
      const Aabb& actual = gpu_.fatBox(handle.gpuProxy);
      if (expected.min != actual.min || expected.max != actual.max) {
        ++tally.mismatches;
        ADD_FAILURE() << "seed " << spec_.seed << ": fat boxes differ";
        return;
      }
    }
  }

  SceneSpec spec_;
  std::mt19937 random_;
  TreeBroadPhase tree_;
  GpuBroadPhase gpu_;
  std::vector<Handle> handles_;
  std::uint32_t nextBody_ = 0;
  std::vector<BodyPair> treePairs_, gpuPairs_;
};

// Sizes log-uniform over 2..2000 with both ends always present; kinds and
// options cycle so every kind meets every margin and prediction.
std::vector<SceneSpec> sceneSpecs(int count) {
  std::mt19937 random(20260);
  std::uniform_real_distribution<double> logSize(std::log(2.0), std::log(2000.0));
  const double margins[] = {0.0, 0.125, 0.1};
  const double predictions[] = {0.0, 2.0};
  std::vector<SceneSpec> specs;
  for (int index = 0; index < count; ++index) {
    SceneSpec spec;
    spec.seed = 1000 + static_cast<unsigned>(index);
    spec.proxies = index == 0 ? 2 : index == 1 ? 2000 : static_cast<int>(std::exp(logSize(random)));
    spec.kind = static_cast<SceneKind>(index % 5);
    if (spec.kind == SceneKind::Identical) spec.proxies = std::min(spec.proxies, 300);  // every box meets every box
    spec.options.margin = margins[index % 3];
    spec.options.velocityPrediction = predictions[(index / 3) % 2];
    specs.push_back(spec);
  }
  return specs;
}

TEST(GpuBroadPhase, PairsAndFatBoxesEqualTheTreeAfterEveryFindPairs) {
  Tally tally;
  for (const SceneSpec& spec : sceneSpecs(120)) {
    Comparison comparison(spec);
    comparison.run(spec.proxies > 500 ? 12 : 30, tally);
  }
  std::printf("findPairs calls %lld, pairs compared %lld, mismatches %lld\n", tally.findPairsCalls, tally.pairsCompared,
              tally.mismatches);
  RecordProperty("findPairsCalls", std::to_string(tally.findPairsCalls));
  RecordProperty("pairsCompared", std::to_string(tally.pairsCompared));
  RecordProperty("mismatches", std::to_string(tally.mismatches));
  EXPECT_EQ(tally.mismatches, 0);
}

TEST(GpuBroadPhase, UploadsOnlyChangedBoxesAndGrowsAnOverflowingPairList) {
  GpuBroadPhase gpu(sharedContext(), DynamicAabbTreeOptions{});
  // 600 identical dynamic boxes: 179700 pairs, far past the first pair list.
  const Aabb box{Vec3::Zero(), Vec3::Ones()};
  for (std::uint32_t body = 0; body < 600; ++body) gpu.addProxy(box, body, ProxyMotion::Dynamic);
  std::vector<BodyPair> pairs;
  gpu.findPairs(pairs);
  EXPECT_EQ(pairs.size(), 600u * 599u / 2);
  EXPECT_EQ(gpu.lastTimings().boxesUploaded, 600);
  EXPECT_EQ(gpu.lastTimings().candidatePairs, 600 * 599 / 2);
  EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
  gpu.findPairs(pairs);
  EXPECT_EQ(gpu.lastTimings().boxesUploaded, 0);
  EXPECT_EQ(pairs.size(), 600u * 599u / 2);
  gpu.moveProxy(7, Aabb{Vec3::Constant(0.01), Vec3::Constant(1.01)}, Vec3::Zero());  // inside its fat box
  gpu.moveProxy(8, Aabb{Vec3::Constant(5.0), Vec3::Constant(6.0)}, Vec3::Zero());    // out of it
  gpu.findPairs(pairs);
  EXPECT_EQ(gpu.lastTimings().boxesUploaded, 1);
  EXPECT_EQ(pairs.size(), 599u * 598u / 2);
  EXPECT_EQ(gpu.stats().proxiesReinserted, 1);
}

TEST(GpuBroadPhase, BadInputThrows) {
  GpuBroadPhase gpu(sharedContext(), DynamicAabbTreeOptions{});
  EXPECT_THROW(gpu.removeProxy(0), std::invalid_argument);
  const int proxy = gpu.addProxy(Aabb{Vec3::Zero(), Vec3::Ones()}, 3, ProxyMotion::Dynamic);
  EXPECT_THROW(gpu.moveProxy(proxy, Aabb{Vec3::Ones(), Vec3::Zero()}, Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(gpu.moveProxy(proxy, Aabb{Vec3::Zero(), Vec3::Ones()}, Vec3::Constant(NAN)), std::invalid_argument);
  gpu.removeProxy(proxy);
  EXPECT_THROW(gpu.fatBox(proxy), std::invalid_argument);
  EXPECT_THROW(gpu.setProxyActive(proxy, false), std::invalid_argument);
  DynamicAabbTreeOptions negative;
  negative.margin = -1.0;
  EXPECT_THROW(GpuBroadPhase(sharedContext(), negative), std::invalid_argument);
}

// Timings for the report, not a check: run with --gtest_also_run_disabled_tests.
TEST(GpuBroadPhase, DISABLED_TimesFindPairsAgainstTheTree) {
  for (const int count : {1000, 4000, 16000}) {
    SceneSpec spec{7, count, SceneKind::Scattered, DynamicAabbTreeOptions{}};
    std::mt19937 random(spec.seed);
    TreeBroadPhase tree(spec.options);
    GpuBroadPhase gpu(sharedContext(), spec.options);
    std::vector<Aabb> tight;
    std::vector<int> treeIds, gpuIds;
    for (int index = 0; index < count; ++index) {
      tight.push_back(sceneBox(spec, random));
      treeIds.push_back(tree.addProxy(tight.back(), index, ProxyMotion::Dynamic));
      gpuIds.push_back(gpu.addProxy(tight.back(), index, ProxyMotion::Dynamic));
    }
    std::vector<BodyPair> treePairs, gpuPairs;
    tree.findPairs(treePairs);
    gpu.findPairs(gpuPairs);
    double treeSeconds = 0, gpuSeconds = 0;
    GpuBroadPhaseTimings sum;
    constexpr int steps = 20;
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    for (int step = 0; step < steps; ++step) {
      for (int index = 0; index < count; ++index) {
        const Vec3 move(small(random), small(random), small(random));
        tight[index] = Aabb{tight[index].min + move, tight[index].max + move};
        tree.moveProxy(treeIds[index], tight[index], move);
        gpu.moveProxy(gpuIds[index], tight[index], move);
      }
      auto start = std::chrono::steady_clock::now();
      tree.findPairs(treePairs);
      treeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      start = std::chrono::steady_clock::now();
      gpu.findPairs(gpuPairs);
      gpuSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      sum.uploadSeconds += gpu.lastTimings().uploadSeconds;
      sum.dispatchSeconds += gpu.lastTimings().dispatchSeconds;
      sum.readbackSeconds += gpu.lastTimings().readbackSeconds;
      sum.boxesUploaded += gpu.lastTimings().boxesUploaded;
      ASSERT_EQ(treePairs, gpuPairs);
    }
    std::printf(
        "%5d proxies, %zu pairs: tree %.3f ms, GPU %.3f ms (upload %.3f, dispatch %.3f, readback %.3f; %d boxes "
        "uploaded per call)\n",
        count, gpuPairs.size(), 1e3 * treeSeconds / steps, 1e3 * gpuSeconds / steps, 1e3 * sum.uploadSeconds / steps,
        1e3 * sum.dispatchSeconds / steps, 1e3 * sum.readbackSeconds / steps, sum.boxesUploaded / steps);
  }
}

}  // namespace
}  // namespace physdbg::gpu
