// Tree rotations. At node A with children B and C, swapping B with one of
// C's children (or C with one of B's) changes only the box of the child that
// receives the swapped-in subtree; A's box stays the same. We take the swap
// that shrinks that box's area most, if any does. This undoes the long
// chains that sorted insertion builds, at O(1) per ancestor.
#include <algorithm>

#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {

void DynamicAabbTree::rotate(int node) {
  const int b = nodes_[node].child1;
  const int c = nodes_[node].child2;
  double bestDelta = 0.0;
  int upper = nullNode;
  int lower = nullNode;
  // upper moves down to replace lower, whose new sibling is `kept` under `parent`.
  auto consider = [&](int up, int parent, int low, int kept) {
    const double delta = nodes_[up].box.merged(nodes_[kept].box).surfaceArea() - nodes_[parent].box.surfaceArea();
    if (delta < bestDelta) {
      bestDelta = delta;
      upper = up;
      lower = low;
    }
  };
  if (nodes_[c].child1 != nullNode) {
    consider(b, c, nodes_[c].child1, nodes_[c].child2);
    consider(b, c, nodes_[c].child2, nodes_[c].child1);
  }
  if (nodes_[b].child1 != nullNode) {
    consider(c, b, nodes_[b].child1, nodes_[b].child2);
    consider(c, b, nodes_[b].child2, nodes_[b].child1);
  }
  // A relative threshold keeps rounding noise from flipping equal-area layouts.
  if (upper == nullNode || bestDelta > -1e-12 * nodes_[node].box.surfaceArea()) return;
  if (!logRotations_) {
    swapSubtrees(node, upper, lower);
    return;
  }
  RotationEvent event;
  event.node = node;
  event.first = upper;
  event.second = lower;
  event.firstBox = nodes_[upper].box;
  event.secondBox = nodes_[lower].box;
  event.areaBefore = nodes_[nodes_[lower].parent].box.surfaceArea();
  event.sarBefore = surfaceAreaRatio();
  const int changed = nodes_[lower].parent;
  swapSubtrees(node, upper, lower);
  event.areaAfter = nodes_[changed].box.surfaceArea();
  event.sarAfter = surfaceAreaRatio();
  rotationLog_.push_back(event);
}

void DynamicAabbTree::swapSubtrees(int node, int upper, int lower) {
  const int parent = nodes_[lower].parent;
  Node& top = nodes_[node];
  (top.child1 == upper ? top.child1 : top.child2) = lower;
  Node& middle = nodes_[parent];
  (middle.child1 == lower ? middle.child1 : middle.child2) = upper;
  nodes_[lower].parent = node;
  nodes_[upper].parent = parent;
  refitNode(parent);
  top.height = 1 + std::max(nodes_[top.child1].height, nodes_[top.child2].height);
}

}  // namespace physdbg
