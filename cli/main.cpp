// physdbg: the command that wires scenes, the engine, the renderer and the
// benchmarks together. Exit codes: 0 success, 1 the run itself failed (for
// example a body became NaN), 2 bad usage or bad input.
#include <exception>
#include <iostream>
#include <new>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "scenes/scene.h"

namespace {

using physdbg::cli::Subcommand;

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> commands = {
      {"scenes", "list the built-in scenes", physdbg::cli::runScenes},
      {"simulate", "run a scene without rendering; summary, CSV trace, state hash", physdbg::cli::runSimulate},
      {"render", "simulate a scene and write a PNG frame sequence (and an MP4)", physdbg::cli::runRender},
      {"contacts", "every contact of a scene's initial state or of any step: normal, depth, points (JSON)",
       physdbg::cli::runContacts},
      {"tree", "frame pairs before/after each tree rotation, hierarchy diagram, SAR/height plot",
       physdbg::cli::runTree},
      {"record", "simulate a scene and write its debug-draw primitive stream to a file", physdbg::cli::runRecord},
      {"replay", "render a recording (or a frame range of it) to PNGs, no engine needed", physdbg::cli::runReplay},
      {"bench", "run benchmarks side by side with peer engines, print JSON", physdbg::cli::runBench},
      {"compare", "compare two PNGs like the golden tests; prints figures, writes a diff image",
       physdbg::cli::runCompare},
      {"report", "stability, accuracy and stage reports: PASS/FAIL tables, CSV, plots", physdbg::cli::runReport},
      {"diff", "first step, body and field where two simulate traces differ; both runs drawn there",
       physdbg::cli::runDiff},
      {"plot", "line plot of CSV columns (simulate --series) into a PNG", physdbg::cli::runPlot},
      {"golden", "approve and check golden images of your own scenes (manifest, HTML report, JUnit)",
       physdbg::cli::runGolden},
      {"gpu-info", "the GL context's renderer, version and compute limits (for --collision gpu)",
       physdbg::cli::runGpuInfo},
  };
  return commands;
}

void printUsage(std::ostream& out) {
  out << "usage: physdbg COMMAND [ARGS...]\n\nphysdbg: rigid-body physics with a visual debugger.\n\ncommands:\n";
  for (const Subcommand& command : subcommands()) {
    std::string name = "  " + command.name;
    name.resize(14, ' ');
    out << name << command.summary << "\n";
  }
  out << "\nRun 'physdbg COMMAND --help' for a command's options.\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    printUsage(std::cerr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    printUsage(std::cout);
    return 0;
  }
  const std::vector<std::string> args(argv + 2, argv + argc);
  for (const Subcommand& command : subcommands()) {
    if (command.name != name) continue;
    try {
      return command.run(args);
    } catch (const physdbg::cli::UsageError& error) {
      std::cerr << "physdbg " << name << ": " << error.what() << "\n";
      return 2;
    } catch (const physdbg::SceneError& error) {
      std::cerr << "physdbg " << name << ": " << error.what() << "\n";
      return 2;
    } catch (const std::invalid_argument& error) {
      std::cerr << "physdbg " << name << ": " << error.what() << "\n";
      return 2;
    } catch (const std::bad_alloc&) {
      std::cerr << "physdbg " << name << ": out of memory\n";
      return 1;
    } catch (const std::exception& error) {
      std::cerr << "physdbg " << name << ": error: " << error.what() << "\n";
      return 1;
    }
  }
  std::cerr << "physdbg: unknown command '" << name << "'\n\n";
  printUsage(std::cerr);
  return 2;
}
