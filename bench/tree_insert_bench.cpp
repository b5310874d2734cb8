// "insert/remove": throughput of one-by-one insertion and removal, ours and
// btDbvt, plus the quality the one-by-one tree reaches against a top-down build
// (the "no degradation at 30k bodies" check).
#include <algorithm>
#include <numeric>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/tree_bench.h"
#include "bench/tree_bench_support.h"
#include "bench/tree_bullet_peer.h"
#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg::bench {
namespace {

double millionsPerSecond(long long operations, double ms) { return ms > 0.0 ? operations / ms / 1000.0 : 0.0; }

struct TreeFigures {
  double insertMs, removeMs, sar, topDownSar;
  int height;
};

TreeFigures measureOurs(const std::vector<Aabb>& boxes, const std::vector<int>& removalOrder,
                        const DynamicAabbTreeOptions& options) {
  DynamicAabbTree tree(options);
  std::vector<int> proxies(boxes.size());
  TreeFigures figures{};
  figures.insertMs = millisecondsOf([&] {
    for (std::size_t i = 0; i < boxes.size(); ++i) proxies[i] = tree.createProxy(boxes[i], 0);
  });
  figures.sar = tree.surfaceAreaRatio();
  figures.height = tree.height();
  DynamicAabbTree rebuilt = tree;
  rebuilt.rebuildTopDown();
  figures.topDownSar = rebuilt.surfaceAreaRatio();
  figures.removeMs = millisecondsOf([&] {
    for (const int index : removalOrder) tree.destroyProxy(proxies[index]);
  });
  return figures;
}

void runInsertRemove(const std::string& name, const std::vector<Aabb>& boxes, const BenchSink& sink) {
  std::vector<int> removalOrder(boxes.size());
  std::iota(removalOrder.begin(), removalOrder.end(), 0);
  std::shuffle(removalOrder.begin(), removalOrder.end(), std::mt19937(77));

  DynamicAabbTreeOptions options;
  options.margin = 0.0;  // btDbvt stores exact boxes
  const TreeFigures ours = measureOurs(boxes, removalOrder, options);
  options.insertion = InsertionMethod::Greedy;
  const TreeFigures greedy = measureOurs(boxes, removalOrder, options);
  const double insertMs = ours.insertMs;
  const double removeMs = ours.removeMs;
  const double sar = ours.sar;
  const int height = ours.height;
  const auto peer = bulletDbvtInsertRemove(boxes, removalOrder);
  const long long operations = 2LL * static_cast<long long>(boxes.size());
  nlohmann::json record = benchRecord(name, static_cast<long long>(boxes.size()), insertMs + removeMs,
                                      peer ? "bullet-btDbvt" : "", peer ? peer->insertMs + peer->removeMs : 0.0);
  record["unit"] = "ms to insert all then remove all";
  record["ours_mops"] = millionsPerSecond(operations, insertMs + removeMs);
  record["ours_insert_mops"] = millionsPerSecond(static_cast<long long>(boxes.size()), insertMs);
  record["ours_remove_mops"] = millionsPerSecond(static_cast<long long>(boxes.size()), removeMs);
  record["sar"] = sar;
  record["height"] = height;
  record["topdown_sar"] = ours.topDownSar;
  record["sar_vs_topdown"] = sar / ours.topDownSar;
  record["greedy_mops"] = millionsPerSecond(operations, greedy.insertMs + greedy.removeMs);
  record["greedy_insert_mops"] = millionsPerSecond(static_cast<long long>(boxes.size()), greedy.insertMs);
  record["greedy_sar_vs_topdown"] = greedy.sar / greedy.topDownSar;
  record["greedy_height"] = greedy.height;
  if (peer) {
    record["peer_mops"] = millionsPerSecond(operations, peer->insertMs + peer->removeMs);
    record["peer_insert_mops"] = millionsPerSecond(static_cast<long long>(boxes.size()), peer->insertMs);
    record["peer_sar"] = peer->sar;
    record["peer_height"] = peer->height;
  } else {
    record["peer_note"] = "Bullet not built in";
  }
  sink(record);
}

}  // namespace

void runInsertRemoveCase(const BenchOptions& options, const BenchSink& sink) {
  const std::vector<int> counts = options.quick ? std::vector<int>{1024} : std::vector<int>{8192, 32768};
  for (const int count : counts) {
    runInsertRemove("insert-remove/random", boxesInCube(count, 99), sink);
    runInsertRemove("insert-remove/sorted", sortedLattice(count), sink);
  }
}

}  // namespace physdbg::bench
