#pragma once
// Draws the broad-phase tree into a debug-draw frame for the `tree` (and
// `fat`) layers: internal nodes as blue wire boxes that fade with depth,
// leaves' fat boxes in green, and the boxes of logged rotations.
#include "debugdraw/primitives.h"
#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {

struct TreeDrawOptions {
  bool internalNodes = true;
  bool leaves = true;
  int maxDepth = 1 << 30;  // deeper nodes are skipped (a 30k-body tree is a blur otherwise)
  int minDepth = 0;        // shallower nodes are skipped (to look inside a big tree)
};

void drawTree(const DynamicAabbTree& tree, const TreeDrawOptions& options, debugdraw::Frame& frame);

// Both subtrees of each rotation, as they were just after the swap, joined by a line.
void drawRotations(const std::vector<RotationEvent>& events, debugdraw::Frame& frame);

}  // namespace physdbg
