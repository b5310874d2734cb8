// Top-down rebuild with binned SAH: the reference quality that incremental
// insertion is measured against. Leaves (proxy ids, boxes, user data) stay;
// every internal node is rebuilt.
#include <algorithm>
#include <array>
#include <limits>

#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {
namespace {

constexpr int binCount = 16;

struct Bin {
  Aabb box;
  int count = 0;
};

}  // namespace

void DynamicAabbTree::rebuildTopDown() {
  std::vector<int> leaves;
  leaves.reserve(proxyCount_);
  for (int index = 0; index < static_cast<int>(nodes_.size()); ++index) {
    if (nodes_[index].height > 0) {
      freeNode(index);
    } else if (nodes_[index].height == 0) {
      leaves.push_back(index);
    }
  }
  root_ = leaves.empty() ? nullNode : buildTopDown(leaves, 0, static_cast<int>(leaves.size()));
  if (root_ != nullNode) nodes_[root_].parent = nullNode;
}

int DynamicAabbTree::buildTopDown(std::vector<int>& leaves, int begin, int end) {
  if (end - begin == 1) return leaves[begin];
  Aabb centroids{nodes_[leaves[begin]].box.center(), nodes_[leaves[begin]].box.center()};
  for (int i = begin + 1; i < end; ++i) {
    const Vec3 c = nodes_[leaves[i]].box.center();
    centroids = centroids.merged({c, c});
  }
  int axis = 0;
  (centroids.max - centroids.min).maxCoeff(&axis);
  const double low = centroids.min[axis];
  const double extent = centroids.max[axis] - low;
  int middle = begin + (end - begin) / 2;
  if (extent > 0.0) {
    auto binOf = [&](int leaf) {
      const int bin = static_cast<int>(binCount * (nodes_[leaf].box.center()[axis] - low) / extent);
      return std::min(bin, binCount - 1);
    };
    std::array<Bin, binCount> bins;
    for (int i = begin; i < end; ++i) {
      Bin& bin = bins[binOf(leaves[i])];
      bin.box = bin.count == 0 ? nodes_[leaves[i]].box : bin.box.merged(nodes_[leaves[i]].box);
      ++bin.count;
    }
    // Sweep from the right to get each suffix's area, then from the left to price each split.
    std::array<double, binCount> rightCost{};
    Aabb right;
    int rightCount = 0;
    for (int b = binCount - 1; b > 0; --b) {
      if (bins[b].count > 0) right = rightCount == 0 ? bins[b].box : right.merged(bins[b].box);
      rightCount += bins[b].count;
      rightCost[b] = rightCount == 0 ? 0.0 : right.surfaceArea() * rightCount;
    }
    Aabb left;
    int leftCount = 0;
    double bestCost = std::numeric_limits<double>::infinity();
    int bestSplit = 1;
    for (int b = 0; b < binCount - 1; ++b) {
      if (bins[b].count > 0) left = leftCount == 0 ? bins[b].box : left.merged(bins[b].box);
      leftCount += bins[b].count;
      if (leftCount == 0 || leftCount == end - begin) continue;
      const double cost = left.surfaceArea() * leftCount + rightCost[b + 1];
      if (cost < bestCost) {
        bestCost = cost;
        bestSplit = b + 1;
      }
    }
    const auto split = std::stable_partition(leaves.begin() + begin, leaves.begin() + end,
                                             [&](int leaf) { return binOf(leaf) < bestSplit; });
    middle = static_cast<int>(split - leaves.begin());
  }
  // Coincident centroids: halve the range, which keeps the depth logarithmic.
  const int first = buildTopDown(leaves, begin, middle);
  const int second = buildTopDown(leaves, middle, end);
  const int node = allocateNode();
  nodes_[node].child1 = first;
  nodes_[node].child2 = second;
  nodes_[first].parent = node;
  nodes_[second].parent = node;
  refitNode(node);
  return node;
}

}  // namespace physdbg
