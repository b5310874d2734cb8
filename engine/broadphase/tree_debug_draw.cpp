#include "engine/broadphase/tree_debug_draw.h"

#include <algorithm>

namespace physdbg {
namespace {

debugdraw::WireBox wireBox(const Aabb& box, debugdraw::Color color) {
  return {box.center(), Quat::Identity(), box.halfExtents(), color};
}

}  // namespace

void drawTree(const DynamicAabbTree& tree, const TreeDrawOptions& options, debugdraw::Frame& frame) {
  const int height = std::max(1, tree.height());
  tree.forEachNode([&](const Aabb& box, int depth, bool isLeaf) {
    if (depth < options.minDepth || depth > options.maxDepth) return;
    if (isLeaf) {
      if (options.leaves) frame.wireBoxes.push_back(wireBox(box, debugdraw::colors::fatBox));
      return;
    }
    if (!options.internalNodes) return;
    debugdraw::Color color = debugdraw::colors::treeNode;
    // The root is opaque, the deepest level faint: nesting stays readable.
    color.a = 1.0f - 0.75f * static_cast<float>(depth) / static_cast<float>(height);
    frame.wireBoxes.push_back(wireBox(box, color));
  });
}

void drawRotations(const std::vector<RotationEvent>& events, debugdraw::Frame& frame) {
  const debugdraw::Color color{1.0f, 0.3f, 1.0f, 1.0f};  // magenta: not used by any other layer
  for (const RotationEvent& event : events) {
    frame.wireBoxes.push_back(wireBox(event.firstBox, color));
    frame.wireBoxes.push_back(wireBox(event.secondBox, color));
    frame.lines.push_back({event.firstBox.center(), event.secondBox.center(), color});
  }
}

}  // namespace physdbg
