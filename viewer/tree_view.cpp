#include "viewer/tree_view.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "viewer/line_plot.h"
#include "viewer/pixel_canvas.h"
#include "viewer/tree_diagram.h"

namespace physdbg::viewer {
namespace {

namespace dd = debugdraw;

TreeHighlight highlightOf(const TreeEvent& event) {
  TreeHighlight highlight;
  highlight.newLeaf = event.leaf;
  for (const RotationEvent& rotation : event.rotations) {
    highlight.movedDown.push_back(rotation.first);
    highlight.movedUp.push_back(rotation.second);
    highlight.pivots.push_back(rotation.node);
    for (int node : reshapedBy(rotation, event.after)) highlight.reshaped.push_back(node);
  }
  return highlight;
}

std::string stateLine(const char* label, const TreeSnapshot& tree) {
  char line[128];
  std::snprintf(line, sizeof line, "%s SAR %.3f  height %d", label, tree.surfaceAreaRatio(), tree.height());
  return line;
}

void addLegend(const TreeEvent& event, bool after, int height, dd::Frame& frame) {
  const std::string title = event.what + (after ? ": AFTER " : ": BEFORE ") + std::to_string(event.rotations.size()) +
                            (event.rotations.size() == 1 ? " rotation" : " rotations");
  frame.texts.push_back({10, 8, 2, title, {1, 1, 1, 1}});
  frame.texts.push_back({10, 30, 1.5f, stateLine("before:", event.before),
                         after ? dd::Color{0.7f, 0.7f, 0.7f, 1} : dd::Color{1, 1, 1, 1}});
  frame.texts.push_back({10, 46, 1.5f, stateLine("after: ", event.after),
                         after ? dd::Color{1, 1, 1, 1} : dd::Color{0.7f, 0.7f, 0.7f, 1}});
  float y = 62;
  for (const RotationEvent& rotation : event.rotations) {
    for (int node : reshapedBy(rotation, event.after)) {
      char line[160];
      std::snprintf(line, sizeof line, "orange box (node %d) area %.3g -> %.3g", node,
                    event.before.nodes[node].box.surfaceArea(), event.after.nodes[node].box.surfaceArea());
      frame.texts.push_back({10, y, 1.5f, line, treecolors::reshaped});
      y += 14;
    }
  }
  y = static_cast<float>(height - 20);
  float x = 10;
  for (const auto& [text, color] : {std::pair{"moved down", treecolors::movedDown},
                                    {"moved up", treecolors::movedUp},
                                    {"pivot", treecolors::pivot},
                                    {"changed box", treecolors::reshaped},
                                    {"new leaf", treecolors::newLeaf},
                                    {"depth: blue..red", depthColor(0, 1)}}) {
    frame.texts.push_back({x, y, 1.5f, text, color});
    x += 9.0f * static_cast<float>(std::string(text).size()) + 18.0f;
  }
}

}  // namespace

render::Image renderTreeEventFrame(TreePanels& panels, const TreeEvent& event, bool after,
                                   const render::Camera& camera) {
  const TreeSnapshot& tree = after ? event.after : event.before;
  const TreeHighlight highlight = highlightOf(event);
  dd::Frame boxes;
  drawTreeBoxes(tree, highlight, panels.margin, boxes);
  boxes.texts.push_back({10, 8, 1.5f, "3D: below the pivots, leaves solid and internal nodes wire", {1, 1, 1, 1}});
  const render::Image view = panels.renderer.render(boxes, camera);
  dd::Frame diagram;
  const int width = panels.width, height = panels.height;
  drawTreeDiagram(tree, highlight, 10, 62 + 14.0 * event.rotations.size(), width - 20,
                  height - 92 - 14.0 * event.rotations.size(), diagram);
  addLegend(event, after, height, diagram);
  return sideBySide(view, panels.renderer.render(diagram, pixelCamera(width, height)));
}

render::Camera treeEventCamera(const TreeEvent& event, double aspect) {
  render::Bounds bounds;
  for (const RotationEvent& rotation : event.rotations) {
    const Aabb& box = event.after.nodes[rotation.node].box;
    const Vec3 margin = 0.15 * (box.max - box.min) + Vec3::Constant(0.5);
    bounds.extend(box.min - margin);
    bounds.extend(box.max + margin);
  }
  return render::frameBoundsCamera(bounds, aspect);
}

TreePlot renderTreePlot(TreePanels& panels, const std::vector<Aabb>& boxes) {
  DynamicAabbTreeOptions with;
  with.margin = panels.margin;
  DynamicAabbTreeOptions without = with;
  without.rotations = false;
  TreePlot plot;
  const TreeCurves& on = plot.withRotations = insertionCurves(boxes, with);
  const TreeCurves& off = plot.withoutRotations = insertionCurves(boxes, without);
  const dd::Color onColor{1.0f, 0.6f, 0.1f, 1}, offColor{0.4f, 0.6f, 1.0f, 1};
  const int width = panels.width, height = panels.height;
  dd::Frame sarFrame, heightFrame;
  drawLinePlot({"surface area ratio (lower is better)", {"insertions"}, {"SAR"}},
               {{"rotations", onColor, on.sar}, {"no rotations", offColor, off.sar}},
               {0, 0, double(width), double(height)}, sarFrame);
  drawLinePlot({"tree height", {"insertions"}, {"height (levels)"}},
               {{"rotations", onColor, on.height}, {"no rotations", offColor, off.height}},
               {0, 0, double(width), double(height)}, heightFrame);
  const render::Camera camera = pixelCamera(width, height);
  plot.image = sideBySide(panels.renderer.render(sarFrame, camera), panels.renderer.render(heightFrame, camera));
  return plot;
}

render::Image renderTreeRotationFrame(const SceneDescription& scene, int eventIndex, bool after,
                                      render::Renderer& renderer) {
  TreePanels panels{renderer, renderer.options().width, renderer.options().height};
  std::optional<TreeEvent> wanted;
  TreeEventStream stream{std::max(eventIndex + 1LL, 0LL), [&](const TreeEvent& event, int index) {
                           if (index == eventIndex) wanted = event;
                         }};
  std::vector<Aabb> boxes;
  collectTreeEvents(scene, 0, panels.margin, boxes, stream);
  if (!wanted)
    throw std::invalid_argument("tree view: scene '" + scene.name + "' has " + std::to_string(stream.count) +
                                " rotating insertions, asked for event " + std::to_string(eventIndex));
  return renderTreeEventFrame(panels, *wanted, after, treeEventCamera(*wanted, double(panels.width) / panels.height));
}

}  // namespace physdbg::viewer
