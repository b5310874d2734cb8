// physdbg tree: what the broad-phase tree's rotations do. The scene's bodies
// are inserted one by one into a tree of our own with the rotation log on;
// every insertion (and, with --steps, every reinsertion) that rotates gives a
// before/after pair: 3D boxes beside the hierarchy diagram (viewer/tree_view.h).
// A plot compares SAR and height against insertion count with and without
// rotations.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/limits.h"
#include "cli/output_folder.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/tree_view.h"

namespace physdbg::cli {
namespace {

namespace fs = std::filesystem;
using viewer::TreeEvent;
using viewer::TreePanels;

struct TreeViewSettings {
  std::string outputDirectory;
  int width = 640, height = 480;  // of each panel
  int maxEvents = 12;
  int steps = 0;
  double margin = 0.1;
};

void writePlot(const std::vector<Aabb>& boxes, TreePanels& panels, const std::string& path) {
  const viewer::TreePlot plot = viewer::renderTreePlot(panels, boxes);
  writeOutputPng(path, plot.image, "-o");
  const viewer::TreeCurves &on = plot.withRotations, &off = plot.withoutRotations;
  std::printf("final SAR %.3f with rotations, %.3f without; height %g with, %g without\n",
              on.sar.empty() ? 0.0 : on.sar.back(), off.sar.empty() ? 0.0 : off.sar.back(),
              on.height.empty() ? 0.0 : on.height.back(), off.height.empty() ? 0.0 : off.height.back());
}

// Writes one event's frame pair and prints its line.
void writeEvent(TreePanels& panels, const TreeViewSettings& settings, const TreeEvent& event, int index) {
  const render::Camera camera = viewer::treeEventCamera(event, double(settings.width) / settings.height);
  char name[64];
  for (const bool after : {false, true}) {
    std::snprintf(name, sizeof name, "event_%03d_%s.png", index, after ? "after" : "before");
    writeOutputPng((fs::path(settings.outputDirectory) / name).string(), viewer::renderTreeEventFrame(panels, event, after, camera),
                   "-o");
  }
  int grandchildSwaps = 0;
  for (const RotationEvent& rotation : event.rotations)
    grandchildSwaps += viewer::reshapedBy(rotation, event.after).size() == 2 ? 1 : 0;
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
  std::tie(settings.width, settings.height) = readSize(arguments, defaultPanelSize);
  checkPanelSize(settings, arguments.value("--size", defaultPanelSize));
  settings.maxEvents = arguments.positiveInt("--max-events", 12, limits::maxTreeEvents);
  settings.steps = readSteps(arguments, 0);
  settings.margin = arguments.has("--margin") ? arguments.positiveDouble("--margin", 0.1) : 0.1;
  return settings;
}

}  // namespace

int runTree(const std::vector<std::string>& args) {
  CommandSpec spec{
      "tree",
      "SCENE [-o DIR] [--size WxH] [--max-events N] [--steps N] [--margin M] [--backend osmesa|egl]",
      "Inserts SCENE's bodies one by one into a dynamic AABB tree and writes, for each insertion (and with\n"
      "--steps, each reinsertion) whose refit walk rotates, DIR/event_NNN_before.png and event_NNN_after.png:\n"
      "the 3D boxes beside the hierarchy diagram, with the swapped subtrees highlighted. 'Before' is the tree\n"
      "with the leaf inserted and refitted but not rotated. DIR/sar_height.png plots SAR and height against\n"
      "insertion count with and without rotations.",
      {outputOption("DIR", "output folder (default out/tree_SCENE)"),
       {"--max-events", "", "N", "write at most N frame pairs (default 12)"},
       {"--margin", "", "M", "fat-box margin of the tree (default 0.1)"}},
      1,
      1};
  addOptions(spec, {OptionGroup::PanelSize, OptionGroup::TreeSteps, OptionGroup::Backend, OptionGroup::Solver,
                    OptionGroup::Threads});
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  TreeViewSettings settings = readSettings(*parsed, scene);
  prepareOutputDirectory(settings.outputDirectory);

  render::Renderer renderer({settings.width, settings.height, 0, readBackend(*parsed)});
  TreePanels panels{renderer, settings.width, settings.height, settings.margin};
  viewer::TreeEventStream stream{settings.maxEvents, [&](const TreeEvent& event, int index) {
                                   writeEvent(panels, settings, event, index);
                                 }};
  std::vector<Aabb> boxes;
  viewer::collectTreeEvents(scene, settings.steps, settings.margin, boxes, stream);
  const int written = std::min(settings.maxEvents, stream.count);
  writePlot(boxes, panels, (fs::path(settings.outputDirectory) / "sar_height.png").string());
  std::printf("%d rotating events, wrote %d frame pairs and sar_height.png to %s\n", stream.count, written,
              settings.outputDirectory.c_str());
  return 0;
}

}  // namespace physdbg::cli
