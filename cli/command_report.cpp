// physdbg report stability|accuracy|solver|stages [-o DIR]: the reports of
// issues 9 and 17. Tables go to stdout; with -o the same tables (Markdown,
// CSV), plots and an index.html showing both are written to DIR.
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/accuracy_plots.h"
#include "cli/arguments.h"
#include "cli/bullet_peer_runs.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/output_folder.h"
#include "cli/solver_plots.h"
#include "render/renderer.h"
#include "reports/accuracy_report.h"
#include "reports/html_index.h"
#include "reports/solver_report.h"
#include "reports/stability_report.h"
#include "reports/stage_report.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

// A failed write, checked after writing and after closing, names -o.
void writeText(const std::filesystem::path& path, const std::string& text) {
  errno = 0;
  std::ofstream file(path);
  file << text;
  file.close();
  if (!file) throw outputError("-o", path.string());
}

// Created and checked writable before any case runs.
std::filesystem::path outputDirectory(const Arguments& parsed) {
  const std::string directory = parsed.value("--output");
  if (parsed.has("--output")) prepareOutputDirectory(directory);
  return directory;
}

// The plots' renderer, made only when there is a folder to draw into.
std::unique_ptr<render::Renderer> plotRenderer(const std::filesystem::path& directory) {
  if (directory.empty()) return nullptr;
  return std::make_unique<render::Renderer>(render::RendererOptions{900, 600, 0, render::Backend::OsMesa});
}

// Exit code 1 when any case fails, so scripts can gate on it.
int reportStability(const Arguments& parsed) {
  const auto directory = outputDirectory(parsed);
  const auto length = parsed.has("--quick") ? reports::RunLength::Test : reports::RunLength::Report;
  const auto rows = reports::runStabilitySuite(length, parsed.value("--case"), [](const reports::StabilityRow& row) {
    std::printf("%-22s %-4s %12.4g %-8s %6.2fs  %s\n", row.name.c_str(), row.outcome.pass ? "PASS" : "FAIL",
                row.outcome.figure, row.unit.c_str(), row.seconds, row.outcome.detail.c_str());
    std::fflush(stdout);
  });
  if (rows.empty()) throw UsageError("--case: no stability case matches '" + parsed.value("--case") + "'");
  const std::string markdown = reports::stabilityMarkdown(rows);
  std::cout << "\n" << markdown;
  if (!directory.empty()) {
    writeText(directory / "stability.md", markdown);
    writeText(directory / "stability.csv", reports::stabilityCsv(rows));
    reports::writeHtmlIndex(directory, "physdbg stability", markdown, {});
  }
  for (const auto& row : rows) {
    if (!row.outcome.pass) return 1;
  }
  return 0;
}

int reportAccuracy(const Arguments& parsed) {
  reports::AccuracyOptions options;
  options.quick = parsed.has("--quick");
  options.outputDirectory = outputDirectory(parsed);
  options.peer = bulletSimulation();
  const auto renderer = plotRenderer(options.outputDirectory);
  if (renderer) options.plot = [&](const auto& png, const auto& reference, const auto& methods) {
    writeAccuracyPlot(*renderer, png, reference, methods);
  };
  std::cout << reports::runAccuracyReport(options, [](const std::string& line) {
    std::cout << line << std::endl;
  });
  return 0;
}

int reportSolver(const Arguments& parsed) {
  reports::SolverReportOptions options;
  options.quick = parsed.has("--quick");
  options.outputDirectory = outputDirectory(parsed);
  options.peer = bulletSolverRun();
  const auto renderer = plotRenderer(options.outputDirectory);
  if (renderer) options.plot = [&](const auto& png, const auto& scene, const auto& points) {
    writeSolverPlot(*renderer, png, scene, points);
  };
  const auto progress = [](const std::string& line) { std::cout << line << std::endl; };
  std::cout << reports::runSolverReport(options, progress).markdown;
  return 0;
}

// Spheres only against boxes, no layers against every layer: the counters
// show which stages and layers did work.
int reportStages(const Arguments& parsed) {
  const auto directory = outputDirectory(parsed);
  const int steps = parsed.has("--quick") ? 10 : 120;
  std::string table =
      "| scene | steps | candidate pairs | narrow pairs | closed form | box-box | GJK | EPA | taken again | manifolds "
      "| locked bodies | layers | primitives |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const char* name : {"balls48", "stack", "pyramid"}) {
    for (const char* layers : {"", "shapes,contacts,aabbs"}) {
      const auto c = reports::countStages(resolveScene(name), steps, layers);
      char row[400];
      std::snprintf(row, sizeof row,
                    "| %s | %d | %lld | %lld | %lld | %lld | %lld | %lld | %lld | %lld | %d | %s | %lld |\n",
                    c.scene.c_str(), c.steps, c.candidatePairs, c.narrowPairs, c.fastPath, c.boxBox, c.gjk, c.epa,
                    c.reused, c.manifolds, c.bodiesWithLocks,
                    c.layersRequested.empty() ? "none" : c.layersRequested.c_str(), c.primitivesEmitted);
      table += row;
    }
  }
  std::cout << table;
  if (!directory.empty()) writeText(directory / "stages.md", table);
  return 0;
}

}  // namespace

int runReport(const std::vector<std::string>& args) {
  const CommandSpec spec{"report",
                         "stability|accuracy|solver|stages [-o DIR] [--quick] [--case NAME]",
                         "stability: stiff and extreme scenes, PASS/FAIL with the measured figure (exit 1 if any "
                         "fails).\naccuracy: analytic references swept over dt and solver settings: CSV, "
                         "work-precision plot, convergence orders, Markdown summary.\nsolver: penetration and drift against ms per "
                         "step on stiff stacks, physdbg settings against Bullet's iteration counts.\nstages: which pipeline stages "
                         "and debug layers each scene used, from the engine's counters.",
                         {outputOption("DIR", "also write the tables (and plots) to DIR"),
                          {"--quick", "", "", "short runs (the CTest versions of the stability cases)"},
                          {"--case", "", "NAME", "stability: only the cases whose name contains NAME"}},
                         1,
                         1};
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const std::string kind = parsed->positional()[0];
  if (kind == "stability") return reportStability(*parsed);
  if (kind == "accuracy") return reportAccuracy(*parsed);
  if (kind == "solver") return reportSolver(*parsed);
  if (kind == "stages") return reportStages(*parsed);
  throw UsageError("unknown report '" + kind + "' (stability, accuracy, solver or stages)");
}

}  // namespace physdbg::cli
