#pragma once
// A plain copy of a DynamicAabbTree's shape, indexed by the tree's own node
// ids, that the tree view can edit: undoing a refit walk's rotations gives
// the tree as it was just after the leaf went in, before any rotation.
#include <vector>

#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg::viewer {

struct TreeSnapshot {
  struct Node {
    Aabb box;
    int parent = DynamicAabbTree::nullNode;
    int child1 = DynamicAabbTree::nullNode;
    int child2 = DynamicAabbTree::nullNode;
    bool used = false;
  };
  std::vector<Node> nodes;
  int root = DynamicAabbTree::nullNode;

  bool isLeaf(int node) const { return nodes[node].child1 == DynamicAabbTree::nullNode; }
  int height() const;
  double surfaceAreaRatio() const;  // same definition as the tree's: internal areas over root area
  // Node ids of `node` and everything below it.
  std::vector<int> subtree(int node) const;
  // Depth of every used node (root 0), -1 for unused ids.
  std::vector<int> depths() const;
};

TreeSnapshot snapshotTree(const DynamicAabbTree& tree);

// Swaps `first` and `second` back, newest event first, and refits every
// internal box as the union of its children. Throws std::invalid_argument when
// an event names nodes the snapshot does not hold.
void undoRotations(TreeSnapshot& snapshot, const std::vector<RotationEvent>& events);

}  // namespace physdbg::viewer
