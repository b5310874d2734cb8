#pragma once
// Draws the broad-phase tree into a debug-draw frame for the `tree` (and
// `fat`) layers: internal nodes as blue wire boxes that get paler and fade a
// little with depth (so nesting reads, and a 1000-body tree is not a blue
// mass), a legend naming each depth's colour, leaves' fat boxes in green, and
// the boxes of logged rotations.
#include "debugdraw/primitives.h"
#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {

struct TreeDrawOptions {
  bool internalNodes = true;
  bool leaves = true;
  int maxDepth = 1 << 30;  // deeper nodes are skipped (a 30k-body tree is a blur otherwise)
  int minDepth = 0;        // shallower nodes are skipped (to look inside a big tree)
  // Top-left text, one line a drawn depth in its colour with its box count.
  // It says when nodes have exactly their parent's box: big static bodies
  // (a floor, walls) make chains near the root that draw one box at several depths.
  bool legend = true;
};

// Colour of internal nodes at `depth`: the root is treeNode blue, each level
// paler and a little more transparent, independent of the tree's height so
// a depth keeps its colour from frame to frame.
debugdraw::Color treeNodeColor(int depth);

// The lowest pixel row the legend can reach (its header, at most 14 depth
// lines and "... to N"), whatever the tree: other legends on the left
// go below it and never jump with the tree's height.
float treeLegendBottom();

// Internal nodes are tagged layer Tree, fat leaves layer Fat, both with their
// node, parent (-1 at the root) and depth, so a viewer can filter by depth and
// walk a leaf's path to the root; legend lines carry the depth they name.
void drawTree(const DynamicAabbTree& tree, const TreeDrawOptions& options, debugdraw::Frame& frame);

// Both subtrees of each rotation, as they were just after the swap, joined by a line.
void drawRotations(const std::vector<RotationEvent>& events, debugdraw::Frame& frame);

}  // namespace physdbg
