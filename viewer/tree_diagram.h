#pragma once
// The tree view's two pictures of one tree state: a 2D hierarchy diagram
// (leaves in in-order along x, one row per depth) and the 3D boxes, both
// coloured by depth, with the subtrees a rotation swapped highlighted.
#include <string>
#include <vector>

#include "debugdraw/primitives.h"
#include "viewer/tree_snapshot.h"

namespace physdbg::viewer {

// Colours with a meaning in the tree view.
namespace treecolors {
inline constexpr debugdraw::Color movedDown{1.0f, 0.2f, 1.0f, 1.0f};  // subtree that moved down: magenta
inline constexpr debugdraw::Color movedUp{0.1f, 1.0f, 1.0f, 1.0f};    // subtree that moved up: cyan
inline constexpr debugdraw::Color pivot{1.0f, 1.0f, 1.0f, 1.0f};      // node whose children were swapped
inline constexpr debugdraw::Color newLeaf{1.0f, 0.85f, 0.1f, 1.0f};   // the leaf just inserted: yellow
// Nodes whose box a swap changed (their total area shrinks): orange.
inline constexpr debugdraw::Color reshaped{1.0f, 0.5f, 0.0f, 1.0f};
}  // namespace treecolors

// Depth 0 blue through green to red at `maxDepth`.
debugdraw::Color depthColor(int depth, int maxDepth);

struct TreeHighlight {
  std::vector<int> movedDown, movedUp, pivots;  // subtree roots / pivot nodes
  std::vector<int> reshaped;                    // nodes whose box a swap changed (their total shrank)
  int newLeaf = DynamicAabbTree::nullNode;
};

// Draws the hierarchy into the pixel rectangle (left, top, width, height) of a
// pixel canvas (see pixel_canvas.h).
void drawTreeDiagram(const TreeSnapshot& tree, const TreeHighlight& highlight, double left, double top,
                     double width, double height, debugdraw::Frame& frame);

// Below the pivots: leaves as solid boxes shrunk by `margin` (the bodies'
// tight boxes), internal nodes as wire boxes coloured by depth, highlighted
// subtrees in their colours. Elsewhere only the leaves, as faint wire.
void drawTreeBoxes(const TreeSnapshot& tree, const TreeHighlight& highlight, double margin, debugdraw::Frame& frame);

}  // namespace physdbg::viewer
