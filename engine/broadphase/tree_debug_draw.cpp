#include "engine/broadphase/tree_debug_draw.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace physdbg {
namespace {

namespace dd = debugdraw;

// Deep nodes tend to the palest tree colour; fades no further than this alpha.
constexpr dd::Color kPalestNode{0.8f, 0.88f, 1.0f, 1.0f};
constexpr float kDeepestAlpha = 0.7f;
constexpr float kStepPerDepth = 0.78f;  // share of the remaining change left after each level
constexpr int kMaxLegendDepths = 14;
constexpr float kLegendLeft = 6, kLegendTop = 64, kLegendLineHeight = 11;

dd::WireBox wireBox(const Aabb& box, dd::Color color, const dd::Tag& tag = {}) {
  return {box.center(), Quat::Identity(), box.halfExtents(), color, tag};
}

bool sameBox(const Aabb& a, const Aabb& b) { return a.min == b.min && a.max == b.max; }

// Per depth: how many internal nodes were drawn and how many of them have
// exactly their parent's box (a chain that draws one box several times).
struct DepthCount {
  int nodes = 0, sameAsParent = 0;
};

std::string legendLine(int depth, const DepthCount& count) {
  std::string line = std::to_string(depth) + "  " + std::to_string(count.nodes) + (count.nodes == 1 ? " box" : " boxes");
  if (count.sameAsParent == count.nodes) return line + ", parent's box again";
  if (count.sameAsParent > 0) return line + ", " + std::to_string(count.sameAsParent) + " parent's box again";
  return line;
}

// A tree primitive's tag: a viewer shows or hides it by depth (--tree-depth)
// and finds a body's path to the root (--highlight) by node and parent.
dd::Tag treeTag(dd::Layer layer, int node, int parent, int depth) {
  dd::Tag tag = dd::tagOf(layer);
  tag.node = node;
  tag.parent = parent;
  tag.depth = depth;
  return tag;
}

// A legend line tagged with the depth it names, so filtering by depth keeps
// the lines of the depths shown; the header names none (-1).
dd::Text legendText(float y, std::string text, dd::Color color, int depth) {
  return {kLegendLeft, y, 1, std::move(text), color, treeTag(dd::Layer::Tree, -1, -1, depth)};
}

// Top left, under the two overlay lines (28 px at scale 1, 56 at scale 2).
// The "... to N" line stands for the depths it leaves out: tagged with the first.
void drawLegend(const std::map<int, DepthCount>& counts, dd::Frame& frame) {
  if (counts.empty()) return;
  frame.texts.push_back(legendText(kLegendTop, "tree depth", {1, 1, 1, 1}, -1));
  float y = kLegendTop + kLegendLineHeight;
  int shown = 0;
  for (const auto& [depth, count] : counts) {
    if (++shown > kMaxLegendDepths) {
      frame.texts.push_back(legendText(y, "... to " + std::to_string(counts.rbegin()->first), {1, 1, 1, 1}, depth));
      break;
    }
    dd::Color color = treeNodeColor(depth);
    color.a = 1;  // text must read on its own
    frame.texts.push_back(legendText(y, legendLine(depth, count), color, depth));
    y += kLegendLineHeight;
  }
}

}  // namespace

float treeLegendBottom() { return kLegendTop + kLegendLineHeight * (kMaxLegendDepths + 2); }

dd::Color treeNodeColor(int depth) {
  const float change = 1.0f - std::pow(kStepPerDepth, static_cast<float>(std::max(depth, 0)));
  const dd::Color root = dd::colors::treeNode;
  return {root.r + (kPalestNode.r - root.r) * change, root.g + (kPalestNode.g - root.g) * change,
          root.b + (kPalestNode.b - root.b) * change, 1.0f - (1.0f - kDeepestAlpha) * change};
}

void drawTree(const DynamicAabbTree& tree, const TreeDrawOptions& options, dd::Frame& frame) {
  if (tree.root() == DynamicAabbTree::nullNode) return;
  std::map<int, DepthCount> counts;
  // Depth first, first child first: the order forEachNode gives, kept for recordings.
  struct Visit {
    int node, depth, parent;
  };
  std::vector<Visit> stack{{tree.root(), 0, DynamicAabbTree::nullNode}};
  while (!stack.empty()) {
    const auto [node, depth, parent] = stack.back();
    stack.pop_back();
    const bool leaf = tree.isLeaf(node);
    if (!leaf) {
      stack.push_back({tree.child2(node), depth + 1, node});
      stack.push_back({tree.child1(node), depth + 1, node});
    }
    if (depth < options.minDepth || depth > options.maxDepth) continue;
    if (leaf) {
      if (options.leaves)
        frame.wireBoxes.push_back(
            wireBox(tree.box(node), dd::colors::fatBox, treeTag(dd::Layer::Fat, node, parent, depth)));
      continue;
    }
    if (!options.internalNodes) continue;
    frame.wireBoxes.push_back(
        wireBox(tree.box(node), treeNodeColor(depth), treeTag(dd::Layer::Tree, node, parent, depth)));
    DepthCount& count = counts[depth];
    ++count.nodes;
    if (parent != DynamicAabbTree::nullNode && sameBox(tree.box(node), tree.box(parent))) ++count.sameAsParent;
  }
  if (options.legend) drawLegend(counts, frame);
}

void drawRotations(const std::vector<RotationEvent>& events, dd::Frame& frame) {
  const dd::Color color{1.0f, 0.3f, 1.0f, 1.0f};  // magenta: not used by any other layer
  for (const RotationEvent& event : events) {
    frame.wireBoxes.push_back(wireBox(event.firstBox, color));
    frame.wireBoxes.push_back(wireBox(event.secondBox, color));
    frame.lines.push_back({event.firstBox.center(), event.secondBox.center(), color});
  }
}

}  // namespace physdbg
