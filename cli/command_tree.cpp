// physdbg tree: what the broad-phase tree's rotations do. The scene's bodies
// are inserted one by one into a tree of our own with the rotation log on;
// every insertion (and, with --steps, every reinsertion) that rotates gives a
// before/after pair: 3D boxes beside the hierarchy diagram. A plot compares
// SAR and height against insertion count with and without rotations.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/limits.h"
#include "cli/line_plot.h"
#include "cli/output_folder.h"
#include "cli/pixel_canvas.h"
#include "cli/tree_diagram.h"
#include "cli/tree_view.h"
#include "cli/view_options.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

namespace dd = debugdraw;
namespace fs = std::filesystem;

struct TreeViewSettings {
  std::string outputDirectory;
  int width = 640, height = 480;  // of each panel
  int maxEvents = 12;
  int steps = 0;
  double margin = 0.1;
};

struct TreeEvent {
  std::string what;  // "insertion 12 (body 11)"
  TreeSnapshot before, after;
  std::vector<RotationEvent> rotations;
  int leaf = DynamicAabbTree::nullNode;
};

struct Panels {
  render::Renderer& renderer;
  const TreeViewSettings& settings;
};

// Internal nodes whose boxes a rotation changed: the new parents of the two
// swapped subtrees, except the pivot (its box never changes). One for a
// child-grandchild swap, two for a grandchild-grandchild swap.
std::vector<int> reshapedBy(const RotationEvent& rotation, const TreeSnapshot& after) {
  std::vector<int> nodes;
  for (int moved : {rotation.first, rotation.second}) {
    const int parent = after.nodes[moved].parent;
    if (parent != rotation.node) nodes.push_back(parent);
  }
  return nodes;
}

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

render::Image renderEventFrame(Panels& panels, const TreeEvent& event, bool after, const render::Camera& camera) {
  const TreeSnapshot& tree = after ? event.after : event.before;
  const TreeHighlight highlight = highlightOf(event);
  dd::Frame boxes;
  drawTreeBoxes(tree, highlight, panels.settings.margin, boxes);
  boxes.texts.push_back({10, 8, 1.5f, "3D: below the pivots, leaves solid and internal nodes wire", {1, 1, 1, 1}});
  const render::Image view = panels.renderer.render(boxes, camera);
  dd::Frame diagram;
  const int width = panels.settings.width, height = panels.settings.height;
  drawTreeDiagram(tree, highlight, 10, 62 + 14.0 * event.rotations.size(), width - 20,
                  height - 92 - 14.0 * event.rotations.size(), diagram);
  addLegend(event, after, height, diagram);
  return sideBySide(view, panels.renderer.render(diagram, pixelCamera(width, height)));
}

// Frames the pivots' boxes (everything a rotation touched lies inside them),
// so a small swap is not lost next to a large floor.
render::Camera treeCamera(const TreeEvent& event, double aspect) {
  render::Bounds bounds;
  for (const RotationEvent& rotation : event.rotations) {
    const Aabb& box = event.after.nodes[rotation.node].box;
    const Vec3 margin = 0.15 * (box.max - box.min) + Vec3::Constant(0.5);
    bounds.extend(box.min - margin);
    bounds.extend(box.max + margin);
  }
  return render::frameBoundsCamera(bounds, aspect);
}

std::vector<Aabb> bodyBoxes(const World& world) {
  std::vector<Aabb> boxes;
  for (const RigidBody& body : world.bodies()) boxes.push_back(body.collider().worldBounds(body.transform()));
  return boxes;
}

struct Curves {
  std::vector<double> sar, height;
};

Curves insertionCurves(const std::vector<Aabb>& boxes, const DynamicAabbTreeOptions& options) {
  DynamicAabbTree tree(options);
  Curves curves;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    tree.createProxy(boxes[i], static_cast<std::uint32_t>(i));
    curves.sar.push_back(tree.surfaceAreaRatio());
    curves.height.push_back(tree.height());
  }
  return curves;
}

void writePlot(const std::vector<Aabb>& boxes, const TreeViewSettings& settings, render::Renderer& renderer,
               const std::string& path) {
  DynamicAabbTreeOptions with;
  with.margin = settings.margin;
  DynamicAabbTreeOptions without = with;
  without.rotations = false;
  const Curves on = insertionCurves(boxes, with), off = insertionCurves(boxes, without);
  const dd::Color onColor{1.0f, 0.6f, 0.1f, 1}, offColor{0.4f, 0.6f, 1.0f, 1};
  const int width = settings.width, height = settings.height;
  dd::Frame sarFrame, heightFrame;
  drawLinePlot("surface area ratio (lower is better)", "insertions",
               {{"rotations", onColor, on.sar}, {"no rotations", offColor, off.sar}},
               {0, 0, double(width), double(height)}, sarFrame);
  drawLinePlot("tree height", "insertions", {{"rotations", onColor, on.height}, {"no rotations", offColor, off.height}},
               {0, 0, double(width), double(height)}, heightFrame);
  const render::Camera camera = pixelCamera(width, height);
  writeOutputPng(path, sideBySide(renderer.render(sarFrame, camera), renderer.render(heightFrame, camera)), "-o");
  std::printf("final SAR %.3f with rotations, %.3f without; height %g with, %g without\n",
              on.sar.empty() ? 0.0 : on.sar.back(), off.sar.empty() ? 0.0 : off.sar.back(),
              on.height.empty() ? 0.0 : on.height.back(), off.height.empty() ? 0.0 : off.height.back());
}

// Rotating events as they happen: the first `keep` are snapshotted and handed
// to `onEvent`, the rest only counted. Nothing is kept per event, so memory is
// one tree whatever the scene's size and however many events it makes.
struct EventStream {
  long long keep = 0;
  std::function<void(const TreeEvent& event, int index)> onEvent;
  int count = 0;
};

// Runs `change` with the log cleared; reports an event when it rotated.
template <typename Change>
void observe(DynamicAabbTree& tree, const std::string& what, Change&& change, EventStream& stream) {
  tree.clearRotationLog();
  const int leaf = change();
  if (tree.rotationLog().empty()) return;
  const int index = stream.count++;
  if (index >= stream.keep) return;
  TreeEvent event;
  event.what = what;
  event.leaf = leaf;
  event.rotations = tree.rotationLog();
  event.after = snapshotTree(tree);
  event.before = event.after;
  undoRotations(event.before, event.rotations);
  stream.onEvent(event, index);
}

void collectEvents(const SceneDescription& scene, const TreeViewSettings& settings, std::vector<Aabb>& initialBoxes,
                   EventStream& stream) {
  World world = buildWorld(scene);
  DynamicAabbTreeOptions options;
  options.margin = settings.margin;
  DynamicAabbTree tree(options);
  tree.setRotationLogEnabled(true);
  initialBoxes = bodyBoxes(world);
  std::vector<int> proxies;
  for (std::size_t i = 0; i < initialBoxes.size(); ++i) {
    const std::string what = "insertion " + std::to_string(i + 1) + " (body " + std::to_string(i) + ")";
    observe(
        tree, what,
        [&] {
          proxies.push_back(tree.createProxy(initialBoxes[i], static_cast<std::uint32_t>(i)));
          return proxies.back();
        },
        stream);
  }
  for (int step = 1; step <= settings.steps; ++step) {
    world.step();
    const std::vector<Aabb> boxes = bodyBoxes(world);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::string what = "step " + std::to_string(step) + " reinsertion (body " + std::to_string(i) + ")";
      observe(
          tree, what,
          [&] {
            tree.moveProxy(proxies[i], boxes[i]);
            return proxies[i];
          },
          stream);
    }
  }
}

// Writes one event's frame pair and prints its line.
void writeEvent(Panels& panels, const TreeEvent& event, int index) {
  const TreeViewSettings& settings = panels.settings;
  const render::Camera camera = treeCamera(event, double(settings.width) / settings.height);
  char name[64];
  for (const bool after : {false, true}) {
    std::snprintf(name, sizeof name, "event_%03d_%s.png", index, after ? "after" : "before");
    writeOutputPng((fs::path(settings.outputDirectory) / name).string(), renderEventFrame(panels, event, after, camera),
                   "-o");
  }
  int grandchildSwaps = 0;
  for (const RotationEvent& rotation : event.rotations)
    grandchildSwaps += reshapedBy(rotation, event.after).size() == 2 ? 1 : 0;
  std::printf("event %03d: %s, %zu rotations (%d grandchild swaps), SAR %.3f -> %.3f, height %d -> %d\n", index,
              event.what.c_str(), event.rotations.size(), grandchildSwaps, event.before.surfaceAreaRatio(),
              event.after.surfaceAreaRatio(), event.before.height(), event.after.height());
}

// Both panels side by side make one image: it must fit the image limits too.
void checkPanelSize(const TreeViewSettings& settings, const std::string& text) {
  if (settings.width < 400 || settings.height < 300) throw UsageError("--size: each panel needs at least 400x300");
  const long long width = 2LL * settings.width;
  if (width > limits::maxImageSide || width * settings.height > limits::maxImagePixels)
    throw UsageError("--size: two " + text + " panels side by side make a " + std::to_string(width) + "x" +
                     std::to_string(settings.height) + " image, over " + std::to_string(limits::maxImageSide) +
                     " pixels a side or " + std::to_string(limits::maxImagePixels) + " pixels");
}

TreeViewSettings readSettings(const Arguments& arguments, const SceneDescription& scene) {
  TreeViewSettings settings;
  settings.outputDirectory = arguments.value("--output", sceneOutputFolder(scene.name, "tree_"));
  const std::string size = arguments.value("--size", "640x480");
  std::tie(settings.width, settings.height) = parseSize(size, "--size");
  checkPanelSize(settings, size);
  settings.maxEvents = arguments.positiveInt("--max-events", 12, limits::maxTreeEvents);
  settings.steps = arguments.positiveInt("--steps", 0, static_cast<int>(limits::maxSteps));
  settings.margin = arguments.has("--margin") ? arguments.positiveDouble("--margin", 0.1) : 0.1;
  return settings;
}

}  // namespace

render::Image renderTreeRotationFrame(const SceneDescription& scene, int eventIndex, bool after,
                                      render::Renderer& renderer) {
  TreeViewSettings settings;
  settings.width = renderer.options().width;
  settings.height = renderer.options().height;
  std::optional<TreeEvent> wanted;
  EventStream stream{std::max(eventIndex + 1LL, 0LL), [&](const TreeEvent& event, int index) {
                       if (index == eventIndex) wanted = event;
                     }};
  std::vector<Aabb> boxes;
  collectEvents(scene, settings, boxes, stream);
  if (!wanted)
    throw std::invalid_argument("tree view: scene '" + scene.name + "' has " + std::to_string(stream.count) +
                                " rotating insertions, asked for event " + std::to_string(eventIndex));
  Panels panels{renderer, settings};
  return renderEventFrame(panels, *wanted, after, treeCamera(*wanted, double(settings.width) / settings.height));
}

int runTree(const std::vector<std::string>& args) {
  const CommandSpec spec{
      "tree",
      "SCENE [-o DIR] [--size WxH] [--max-events N] [--steps K] [--margin M] [--backend osmesa|egl]",
      "Inserts SCENE's bodies one by one into a dynamic AABB tree and writes, for each insertion (and with\n"
      "--steps, each reinsertion) whose refit walk rotates, DIR/event_NNN_before.png and event_NNN_after.png:\n"
      "the 3D boxes beside the hierarchy diagram, with the swapped subtrees highlighted. 'Before' is the tree\n"
      "with the leaf inserted and refitted but not rotated. DIR/sar_height.png plots SAR and height against\n"
      "insertion count with and without rotations.",
      {{"--output", "-o", "DIR", "output folder (default out/tree_SCENE)"},
       {"--size", "", "WxH", "size of each of the two panels (default 640x480)"},
       {"--max-events", "", "N", "write at most N frame pairs (default 12)"},
       {"--steps", "", "K", "then simulate K steps and show reinsertions that rotate"},
       {"--margin", "", "M", "fat-box margin of the tree (default 0.1)"},
       backendOptionSpec()},
      1,
      1};
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = resolveScene(parsed->positional()[0]);
  TreeViewSettings settings = readSettings(*parsed, scene);
  prepareOutputDirectory(settings.outputDirectory);

  render::Renderer renderer({settings.width, settings.height, 0, readBackend(*parsed)});
  Panels panels{renderer, settings};
  EventStream stream{settings.maxEvents, [&](const TreeEvent& event, int index) { writeEvent(panels, event, index); }};
  std::vector<Aabb> boxes;
  collectEvents(scene, settings, boxes, stream);
  const int written = std::min(settings.maxEvents, stream.count);
  writePlot(boxes, settings, renderer, (fs::path(settings.outputDirectory) / "sar_height.png").string());
  std::printf("%d rotating events, wrote %d frame pairs and sar_height.png to %s\n", stream.count, written,
              settings.outputDirectory.c_str());
  return 0;
}

}  // namespace physdbg::cli
