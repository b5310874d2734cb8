#include "viewer/tree_diagram.h"

#include <algorithm>
#include <cmath>

#include "viewer/pixel_canvas.h"

namespace physdbg::viewer {
namespace {

namespace dd = debugdraw;
constexpr int none = DynamicAabbTree::nullNode;

// Highlight colour of each node id, or nullptr; a later highlight wins.
std::vector<const dd::Color*> highlightColors(const TreeSnapshot& tree, const TreeHighlight& highlight) {
  std::vector<const dd::Color*> colors(tree.nodes.size(), nullptr);
  auto mark = [&](const std::vector<int>& roots, const dd::Color& color) {
    for (const int root : roots)
      for (const int node : tree.subtree(root)) colors[node] = &color;
  };
  mark(highlight.movedDown, treecolors::movedDown);
  mark(highlight.movedUp, treecolors::movedUp);
  if (highlight.newLeaf >= 0 && highlight.newLeaf < static_cast<int>(colors.size()))
    colors[highlight.newLeaf] = &treecolors::newLeaf;
  return colors;
}

// x of every node in [0, 1]: leaves evenly spaced in in-order, parents midway.
std::vector<double> layoutColumns(const TreeSnapshot& tree, int& leafCount) {
  std::vector<double> column(tree.nodes.size(), 0.0);
  std::vector<int> leaves;
  std::vector<int> stack{tree.root};
  std::vector<int> postOrder;
  while (!stack.empty()) {
    const int node = stack.back();
    stack.pop_back();
    postOrder.push_back(node);
    if (tree.isLeaf(node)) continue;
    stack.push_back(tree.nodes[node].child1);
    stack.push_back(tree.nodes[node].child2);
  }
  // postOrder holds a reversed post-order with child2 first; reversing gives child1 before child2.
  std::reverse(postOrder.begin(), postOrder.end());
  for (const int node : postOrder)
    if (tree.isLeaf(node)) leaves.push_back(node);
  leafCount = static_cast<int>(leaves.size());
  for (int i = 0; i < leafCount; ++i) column[leaves[i]] = (i + 0.5) / leafCount;
  for (const int node : postOrder)
    if (!tree.isLeaf(node))
      column[node] = 0.5 * (column[tree.nodes[node].child1] + column[tree.nodes[node].child2]);
  return column;
}

}  // namespace

dd::Color depthColor(int depth, int maxDepth) {
  const float t = maxDepth > 0 ? static_cast<float>(depth) / static_cast<float>(maxDepth) : 0.0f;
  // Blue -> green -> red, bright enough on the dark background.
  if (t < 0.5f) return {0.2f, 0.4f + 1.1f * t, 1.0f - 1.4f * t, 1.0f};
  return {0.2f + 1.6f * (t - 0.5f), 0.95f - 1.2f * (t - 0.5f), 0.3f, 1.0f};
}

void drawTreeDiagram(const TreeSnapshot& tree, const TreeHighlight& highlight, double left, double top,
                     double width, double height, dd::Frame& frame) {
  if (tree.root == none) return;
  int leafCount = 0;
  const std::vector<double> column = layoutColumns(tree, leafCount);
  const std::vector<int> depth = tree.depths();
  const int maxDepth = std::max(1, tree.height());
  const std::vector<const dd::Color*> colors = highlightColors(tree, highlight);
  const double rowHeight = height / (maxDepth + 1);
  const double halfWidth = std::clamp(0.4 * width / leafCount, 1.0, 8.0);
  const double halfHeight = std::clamp(0.3 * rowHeight, 1.5, 8.0);
  auto x = [&](int node) { return left + width * column[node]; };
  auto y = [&](int node) { return top + rowHeight * (depth[node] + 0.5); };
  for (std::size_t node = 0; node < tree.nodes.size(); ++node) {
    if (!tree.nodes[node].used || depth[node] < 0) continue;
    const int id = static_cast<int>(node);
    const dd::Color color = colors[id] ? *colors[id] : depthColor(depth[id], maxDepth);
    if (!tree.isLeaf(id))
      for (const int child : {tree.nodes[id].child1, tree.nodes[id].child2}) {
        const dd::Color edge = colors[child] ? *colors[child] : dd::Color{0.5f, 0.5f, 0.55f, 1.0f};
        frame.lines.push_back({pixelPoint(x(id), y(id)), pixelPoint(x(child), y(child)), edge});
      }
    frame.boxes.push_back(pixelRectangle(x(id), y(id), halfWidth, halfHeight, color));
  }
  auto frameNodes = [&](const std::vector<int>& nodes, double grow, dd::Color color) {
    for (const int node : nodes) {
      if (node < 0 || node >= static_cast<int>(depth.size()) || depth[node] < 0) continue;
      frame.wireBoxes.push_back({pixelPoint(x(node), y(node)), dd::Quat::Identity(),
                                 {halfWidth + grow, halfHeight + grow, 0.5}, color});
    }
  };
  frameNodes(highlight.pivots, 3, treecolors::pivot);
  frameNodes(highlight.reshaped, 3, treecolors::reshaped);
  frameNodes(highlight.reshaped, 4, treecolors::reshaped);
}

void drawTreeBoxes(const TreeSnapshot& tree, const TreeHighlight& highlight, double margin, dd::Frame& frame) {
  if (tree.root == none) return;
  const std::vector<int> depth = tree.depths();
  const int maxDepth = std::max(1, tree.height());
  const std::vector<const dd::Color*> colors = highlightColors(tree, highlight);
  // Below the pivots is everything a rotation touched; the rest is context,
  // drawn as faint wire so large static boxes do not hide the swap.
  std::vector<bool> focus(tree.nodes.size(), highlight.pivots.empty());
  for (const int pivot : highlight.pivots)
    for (const int node : tree.subtree(pivot)) focus[node] = true;
  for (std::size_t node = 0; node < tree.nodes.size(); ++node) {
    if (!tree.nodes[node].used || depth[node] < 0) continue;
    const int id = static_cast<int>(node);
    const Aabb& box = tree.nodes[id].box;
    if (tree.isLeaf(id)) {
      const Vec3 half = (box.halfExtents().array() - margin).max(0.01 * box.halfExtents().array());
      if (!focus[id]) {
        frame.wireBoxes.push_back({box.center(), dd::Quat::Identity(), half, {0.4f, 0.4f, 0.42f, 1.0f}});
        continue;
      }
      const dd::Color color = colors[id] ? *colors[id] : dd::Color{0.6f, 0.6f, 0.62f, 1.0f};
      frame.boxes.push_back({box.center(), dd::Quat::Identity(), half, color});
      continue;
    }
    if (!focus[id]) continue;
    const dd::Color color = colors[id] ? *colors[id] : depthColor(depth[id], maxDepth);
    // Shallower boxes a little larger, so nested boxes with equal faces stay apart.
    const double grow = 1.0 + 0.02 * (maxDepth - depth[id]);
    frame.wireBoxes.push_back({box.center(), dd::Quat::Identity(), box.halfExtents() * grow, color});
  }
  auto outline = [&](const std::vector<int>& nodes, double grow, dd::Color color) {
    for (const int node : nodes) {
      if (node < 0 || node >= static_cast<int>(depth.size()) || depth[node] < 0) continue;
      const Aabb& box = tree.nodes[node].box;
      frame.wireBoxes.push_back({box.center(), dd::Quat::Identity(), box.halfExtents() * grow, color});
    }
  };
  outline(highlight.pivots, 1.0 + 0.02 * maxDepth + 0.03, treecolors::pivot);
  // Two nested outlines read as a thick line: this is the box the rotation shrank.
  outline(highlight.reshaped, 1.005, treecolors::reshaped);
  outline(highlight.reshaped, 1.015, treecolors::reshaped);
}

}  // namespace physdbg::viewer
