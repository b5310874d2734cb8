// physdbg diff A.csv B.csv: where two runs part. Exit 0 when the traces
// agree, 1 when they differ (values or shape), 2 for bad usage or a trace
// that cannot be read. With --scene-a (and --scene-b, --solver-a/b), the
// first differing step of both runs is drawn side by side.
#include <cstdio>
#include <filesystem>
#include <limits>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/limits.h"
#include "cli/common_options.h"
#include "cli/number_option.h"
#include "cli/output_folder.h"
#include "cli/trace_divergence.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/frame_renderer.h"
#include "viewer/pixel_canvas.h"

namespace physdbg::cli {
namespace {

constexpr char defaultDiffLayers[] = "shapes,contacts,velocities,overlay";

// --scene-X with --solver-X: the run as the trace's simulate ran it.
SceneDescription runScene(const Arguments& parsed, const std::string& side, const std::string& sceneOption) {
  SceneDescription scene = resolveScene(parsed.value(sceneOption));
  if (const std::optional<SolverKind> kind = readSolverKind(parsed, "--solver-" + side)) scene.world.solver.kind = *kind;
  if (const std::optional<int> threads = readThreads(parsed)) scene.world.threads = *threads;
  return scene;
}

// "A: t1.csv, stack, seed": which trace and run a picture shows.
std::string caption(const Arguments& parsed, const std::string& side, const SceneDescription& scene) {
  const std::string file = parsed.positional()[side == "a" ? 0 : 1];
  const std::string name = std::filesystem::path(file).filename().string();
  return (side == "a" ? "A: " : "B: ") + name.substr(0, 32) + ", " + scene.name.substr(0, 32) + ", " +
         solverKindName(scene.world.solver.kind);
}

// Both runs at the first differing step, the differing body highlighted.
void renderDivergence(const Arguments& parsed, const Divergence& divergence, const std::string& output) {
  if (!divergence.step) {
    std::printf("nothing to draw: the traces differ only in their columns; %s not written\n", output.c_str());
    return;
  }
  if (*divergence.step > std::numeric_limits<int>::max() - 1 || *divergence.step > limits::maxFrames)
    throw UsageError("--scene-a: step " + std::to_string(*divergence.step) + " is beyond the frames render draws");
  const SceneDescription first = runScene(parsed, "a", "--scene-a");
  const SceneDescription second = runScene(parsed, "b", parsed.has("--scene-b") ? "--scene-b" : "--scene-a");
  const auto [width, height] = readSize(parsed, "640x480");
  viewer::ViewOptions options;
  options.layers = readLayers(parsed, defaultDiffLayers);
  if (divergence.body) options.highlight = {static_cast<int>(*divergence.body)};
  render::Renderer renderer({width, height, 0, readBackend(parsed)});
  const int step = static_cast<int>(*divergence.step);
  const render::Image image = asUsageError([&] {
    return viewer::sideBySide(viewer::renderViewFrame(renderer, first, step, options, caption(parsed, "a", first)),
                              viewer::renderViewFrame(renderer, second, step, options, caption(parsed, "b", second)));
  });
  writeOutputPng(output, image, "-o");
  std::printf("wrote %s: step %d of A (left) and B (right)\n", output.c_str(), step);
}

}  // namespace

int runDiff(const std::vector<std::string>& args) {
  CommandSpec spec{
      "diff",
      "A.csv B.csv [--tolerance T] [--scene-a SCENE [--scene-b SCENE] [--solver-a K] [--solver-b K] -o FILE.png]",
      "Compares two traces written by 'physdbg simulate --trace' row by row and prints the first step, body and\n"
      "field where they differ by more than T (exit 1), or that they agree (exit 0). A step or body only one\n"
      "trace has, or a column only one has, is a difference too, named with both files' lines. With --scene-a,\n"
      "draws that step of both runs side by side (the body in focus) into FILE.png: --scene-a and --solver-a\n"
      "are the run of A.csv, --scene-b (default: --scene-a) and --solver-b the run of B.csv.",
      {{"--tolerance", "", "T", "absolute difference allowed in every field (default 0: bit for bit)"},
       {"--scene-a", "", "SCENE", "the scene A.csv was simulated from: draw the first differing step"},
       {"--scene-b", "", "SCENE", "the scene B.csv was simulated from (default: --scene-a)"},
       {"--solver-a", "", "seed|sequential_impulse", "the --solver A.csv was simulated with"},
       {"--solver-b", "", "seed|sequential_impulse", "the --solver B.csv was simulated with"},
       outputOption("FILE.png", "the side-by-side picture (with --scene-a)"),
       {"--size", "", "WxH", "size of each of the two pictures (default 640x480)"},
       {"--layers", "", "LIST", std::string("debug layers of the pictures (default ") + defaultDiffLayers + ")"}},
      2,
      2};
  addOptions(spec, {OptionGroup::Backend, OptionGroup::Threads});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const double tolerance =
      numberOption(*parsed, "--tolerance", 0.0, 0.0, std::numeric_limits<double>::max());
  for (const char* option : {"--scene-b", "--solver-a", "--solver-b", "--output", "--size", "--layers", "--threads"})
    if (parsed->has(option) && !parsed->has("--scene-a"))
      throw UsageError(std::string(option) + " draws the runs: it needs --scene-a");
  std::string output;
  if (parsed->has("--scene-a")) {
    output = requiredOutput(*parsed, "FILE.png");
    checkOutputFile(output, "-o");
  }
  TraceReader first(parsed->positional()[0]), second(parsed->positional()[1]);
  const Divergence divergence = findDivergence(first, second, tolerance);
  for (const std::string& line : divergence.lines) std::printf("%s\n", line.c_str());
  if (!output.empty() && divergence.kind == Divergence::Kind::Agree)
    std::printf("nothing to draw: the traces agree; %s not written\n", output.c_str());
  else if (!output.empty())
    renderDivergence(*parsed, divergence, output);
  return divergence.kind == Divergence::Kind::Agree ? 0 : 1;
}

}  // namespace physdbg::cli
