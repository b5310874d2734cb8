// "moving": every proxy jitters every step; time per step to update the broad
// phase and get the pairs, ours and Bullet's btDbvtBroadphase on the same boxes.
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "bench/side_by_side.h"
#include "bench/tree_bench.h"
#include "bench/tree_bench_support.h"
#include "bench/tree_bullet_peer.h"
#include "engine/broadphase/tree_broad_phase.h"
#include "engine/parallel/task_system.h"

namespace physdbg::bench {
namespace {

constexpr double jitterStep = 0.05;

template <typename Pairs>
long long countTightOverlaps(const Pairs& pairs, const std::vector<Aabb>& boxes) {
  long long count = 0;
  for (const auto& [a, b] : pairs) count += boxes[a].overlaps(boxes[b]);
  return count;
}

// Reference count of overlapping tight boxes, through an exact (margin 0) tree.
long long bruteTightOverlaps(const std::vector<Aabb>& boxes) {
  DynamicAabbTreeOptions exact;
  exact.margin = 0.0;
  DynamicAabbTree tree(exact);
  for (std::size_t i = 0; i < boxes.size(); ++i) tree.createProxy(boxes[i], static_cast<std::uint32_t>(i));
  long long count = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    tree.query(boxes[i], [&](int proxy) {
      count += tree.userData(proxy) > i;
      return true;
    });
  }
  return count;
}

// One of our configurations, stepped alongside the peer. Its task system
// runs the pair queries (1 thread: on the caller's thread).
struct Variant {
  Variant(const char* name, const DynamicAabbTreeOptions& options, int threads)
      : name(name), tasks(std::make_unique<TaskSystem>(threads)), broadPhase(options, tasks.get()) {}
  const char* name;
  std::unique_ptr<TaskSystem> tasks;
  TreeBroadPhase broadPhase;
  std::vector<int> proxies;
  std::vector<BodyPair> pairs;
  double ms = 0.0;
  double findMs = 0.0;
  long long reinserted = 0;
  int parallelQuerySteps = 0;  // steps whose pair queries ran in parallel
};

// The same insertion method on one thread: the all-core row's scaling.
std::optional<double> singleThreadMs(const std::vector<Variant>& variants, const Variant& variant) {
  for (const Variant& other : variants) {
    if (std::string(other.name) == variant.name && other.tasks->threadCount() == 1) return other.ms;
  }
  return std::nullopt;
}

void emitVariant(const Variant& variant, std::optional<double> oneThreadMs, int steps, const std::vector<Aabb>& boxes,
                 long long bruteTight, const BulletBroadPhasePeer* peer, double peerMs, const BenchSink& sink) {
  const DynamicAabbTree& tree = variant.broadPhase.tree();
  nlohmann::json record =
      benchRecord(std::string("moving/") + variant.name, static_cast<long long>(boxes.size()), variant.ms / steps,
                  peer != nullptr ? "bullet-btDbvtBroadphase" : "", peerMs / steps);
  const int threads = variant.tasks->threadCount();
  addThreadFields(record, threads, variant.ms / steps,
                  oneThreadMs ? std::optional<double>(*oneThreadMs / steps) : std::nullopt);
  record["steps"] = steps;
  record["find_pairs_ms"] = variant.findMs / steps;  // of ours_ms: the pair queries and merge
  record["unit"] = "ms per step (update every proxy + find pairs)";
  record["margin"] = tree.options().margin;
  record["reinserted_per_step"] = static_cast<double>(variant.reinserted) / steps;
  // Below the minimum an all-core row runs the 1-thread row's code: its
  // scaling is then the host's noise.
  record["parallel_query_minimum"] = TreeBroadPhase::parallelQueryMinimum;
  record["steps_with_parallel_queries"] = variant.parallelQuerySteps;
  record["height"] = tree.height();
  record["sar"] = tree.surfaceAreaRatio();
  std::vector<std::pair<int, int>> indexPairs;
  for (const BodyPair& pair : variant.pairs) indexPairs.emplace_back(pair.a, pair.b);
  const long long tight = countTightOverlaps(indexPairs, boxes);
  record["pairs"] = variant.pairs.size();
  record["tight_pairs"] = tight;
  record["brute_force_tight_pairs"] = bruteTight;
  bool match = tight == bruteTight;
  if (peer != nullptr) {
    const auto peerPairs = peer->pairs();
    const long long peerTight = countTightOverlaps(peerPairs, boxes);
    record["peer_pairs"] = peerPairs.size();
    record["peer_tight_pairs"] = peerTight;
    record["peer_margin"] = 0.05;  // DBVT_BP_MARGIN
    match = match && peerTight == bruteTight;
  } else {
    record["peer_note"] = "Bullet not built in";
  }
  record["tight_pairs_match"] = match;
  sink(record);
}

// Every variant steps in the same loop, so a busy spell of the host falls on
// all of them and on the peer alike. The tree's edits are serial; with more
// than one thread the pair queries run in parallel (tree_broad_phase.h).
void runMoving(int count, int steps, const std::vector<int>& threadCounts, const BenchSink& sink) {
  std::vector<Aabb> boxes = boxesInCube(count, 1234);
  const double side = cubeSideFor(count);
  DynamicAabbTreeOptions greedy;
  greedy.insertion = InsertionMethod::Greedy;
  std::vector<Variant> variants;
  variants.reserve(2 * threadCounts.size());
  for (const int threads : threadCounts) {
    variants.emplace_back("branch-and-bound", DynamicAabbTreeOptions{}, threads);
    variants.emplace_back("greedy", greedy, threads);
  }
  for (Variant& variant : variants) {
    for (int i = 0; i < count; ++i) variant.proxies.push_back(variant.broadPhase.addProxy(boxes[i], i, ProxyMotion::Dynamic));
    variant.broadPhase.findPairs(variant.pairs);
  }
  std::unique_ptr<BulletBroadPhasePeer> peer = BulletBroadPhasePeer::create(boxes);
  if (peer) peer->step(boxes);

  double peerMs = 0.0;
  for (int step = 0; step < steps; ++step) {
    const std::vector<Aabb> previous = boxes;
    jitter(boxes, jitterStep, side, 100 + step);
    for (Variant& variant : variants) {
      variant.ms += millisecondsOf([&] {
        for (int i = 0; i < count; ++i) {
          variant.broadPhase.moveProxy(variant.proxies[i], boxes[i], boxes[i].min - previous[i].min);
        }
        variant.findMs += millisecondsOf([&] { variant.broadPhase.findPairs(variant.pairs); });
      });
      const long long reinserted = variant.broadPhase.stats().proxiesReinserted;
      variant.reinserted += reinserted;
      if (variant.tasks->threadCount() > 1 && reinserted >= TreeBroadPhase::parallelQueryMinimum) {
        ++variant.parallelQuerySteps;
      }
    }
    if (peer) peerMs += peer->step(boxes);
  }
  const long long bruteTight = bruteTightOverlaps(boxes);
  for (const Variant& variant : variants) {
    emitVariant(variant, singleThreadMs(variants, variant), steps, boxes, bruteTight, peer.get(), peerMs, sink);
  }
}

}  // namespace

void runMovingCase(const BenchOptions& options, const BenchSink& sink) {
  const std::vector<int> threadCounts = benchThreadCounts(options);
  if (options.quick) {
    runMoving(512, 5, threadCounts, sink);
    runMoving(2048, 3, threadCounts, sink);
    return;
  }
  runMoving(8192, 300, threadCounts, sink);
  runMoving(32768, 300, threadCounts, sink);
}

}  // namespace physdbg::bench
