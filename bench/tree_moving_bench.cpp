// "moving": every proxy jitters every step; time per step to update the broad
// phase and get the pairs, ours and Bullet's btDbvtBroadphase on the same boxes.
#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/tree_bench.h"
#include "bench/tree_bench_support.h"
#include "bench/tree_bullet_peer.h"
#include "engine/broadphase/tree_broad_phase.h"

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

void runMoving(int count, int steps, const BenchSink& sink) {
  std::vector<Aabb> boxes = boxesInCube(count, 1234);
  const double side = cubeSideFor(count);
  TreeBroadPhase ours;
  std::vector<int> proxies;
  for (int i = 0; i < count; ++i) proxies.push_back(ours.addProxy(boxes[i], i, ProxyMotion::Dynamic));
  std::vector<BodyPair> pairs;
  ours.findPairs(pairs);
  std::unique_ptr<BulletBroadPhasePeer> peer = BulletBroadPhasePeer::create(boxes);
  if (peer) peer->step(boxes);

  double oursMs = 0.0;
  double peerMs = 0.0;
  long long reinserted = 0;
  for (int step = 0; step < steps; ++step) {
    const std::vector<Aabb> previous = boxes;
    jitter(boxes, jitterStep, side, 100 + step);
    oursMs += millisecondsOf([&] {
      for (int i = 0; i < count; ++i) ours.moveProxy(proxies[i], boxes[i], boxes[i].min - previous[i].min);
      ours.findPairs(pairs);
    });
    reinserted += ours.stats().proxiesReinserted;
    if (peer) peerMs += peer->step(boxes);
  }
  nlohmann::json record = benchRecord("moving", count, oursMs / steps, peer ? "bullet-btDbvtBroadphase" : "",
                                      peerMs / steps);
  record["steps"] = steps;
  record["unit"] = "ms per step (update every proxy + find pairs)";
  record["margin"] = ours.tree().options().margin;
  record["reinserted_per_step"] = static_cast<double>(reinserted) / steps;
  record["height"] = ours.tree().height();
  record["sar"] = ours.tree().surfaceAreaRatio();
  std::vector<std::pair<int, int>> oursIndexPairs;
  for (const BodyPair& pair : pairs) oursIndexPairs.emplace_back(pair.a, pair.b);
  const long long tight = bruteTightOverlaps(boxes);
  record["pairs"] = pairs.size();
  record["tight_pairs"] = countTightOverlaps(oursIndexPairs, boxes);
  record["brute_force_tight_pairs"] = tight;
  if (peer) {
    const auto peerPairs = peer->pairs();
    record["peer_pairs"] = peerPairs.size();
    record["peer_tight_pairs"] = countTightOverlaps(peerPairs, boxes);
    record["tight_pairs_match"] = record["peer_tight_pairs"] == record["tight_pairs"] && record["tight_pairs"] == tight;
  } else {
    record["peer_note"] = "Bullet not built in";
    record["tight_pairs_match"] = record["tight_pairs"] == tight;
  }
  sink(record);
}

}  // namespace

void runMovingCase(const BenchOptions& options, const BenchSink& sink) {
  if (options.quick) {
    runMoving(512, 5, sink);
    runMoving(2048, 3, sink);
    return;
  }
  runMoving(8192, 300, sink);
  runMoving(32768, 300, sink);
}

}  // namespace physdbg::bench
