// The solver work-precision sweep and its tables. Each scene runs every
// physdbg setting and then every peer iteration count, one after the other
// in the same process, so both engines' ms per step share the machine's
// state of the moment (the benches' side-by-side approach).
#include "reports/solver_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "reports/html_index.h"
#include "reports/stability_support.h"
#include "scenes/stability_scenes.h"
#include "scenes/stacking_scenes.h"

namespace physdbg::reports {
namespace {

struct Grid {
  std::vector<int> substeps, iterations, peerIterations;
  double seconds;
};

Grid gridFor(bool quick) {
  if (quick) return {{1, 4, 16}, {1, 2}, {5, 10, 20}, 0.25};
  return {{1, 2, 4, 8, 16}, {1, 2, 4}, {1, 2, 5, 10, 20, 50}, 3.0};
}

SceneDescription withoutSleep(SceneDescription scene) {
  scene.world.allowSleep = false;
  scene.world.dt = 1.0 / 60.0;
  return scene;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Untimed, before each engine's timed runs: the first run in a process pays
// for cold caches and first allocations.
constexpr int warmUpSteps = 10;

// max_substeps = substeps: the resting-load stiffening cannot add substeps
// behind the setting's back; nor may a calm island take fewer.
SolverSettings pinned(SolverSettings solver, int substeps, int iterations) {
  solver.kind = SolverKind::SequentialImpulse;
  solver.substeps = substeps;
  solver.maxSubsteps = substeps;
  solver.calmSubsteps = substeps;
  solver.velocityIterations = iterations;
  return solver;
}

// Runs are deterministic, so a repeat changes only the time: short runs
// (tiny scenes take hundredths of a ms per step) are repeated up to 5 times
// while under 0.2 s in all, and keep their fastest time.
SolverMeasure fastestOf(const std::function<SolverMeasure()>& run) {
  const auto start = std::chrono::steady_clock::now();
  SolverMeasure best = run();
  for (int repeat = 1; repeat < 5; ++repeat) {
    if (std::chrono::steady_clock::now() - start > std::chrono::milliseconds(200)) break;
    best.msPerStep = std::min(best.msPerStep, run().msPerStep);
  }
  return best;
}

std::string settingName(int substeps, int iterations) {
  return std::to_string(substeps) + " substeps x " + std::to_string(iterations) + " iter";
}

std::vector<SolverPoint> runScene(const std::string& name, const SceneDescription& scene, const Grid& grid,
                                  const SolverReportOptions& options) {
  const int steps = static_cast<int>(std::lround(grid.seconds / scene.world.dt));
  std::vector<SolverPoint> points;
  runPhysdbgSolver(scene, scene.world.solver, warmUpSteps);
  for (const int substeps : grid.substeps) {
    for (const int iterations : grid.iterations) {
      points.push_back({name, "physdbg", settingName(substeps, iterations), substeps, iterations,
                        fastestOf([&] { return runPhysdbgSolver(scene, pinned(scene.world.solver, substeps, iterations), steps); })});
    }
  }
  const SolverSettings& standard = scene.world.solver;
  points.push_back({name, "physdbg default", "default: " + settingName(standard.substeps, standard.velocityIterations) +
                    ", up to " + std::to_string(standard.maxSubsteps) + " under load",
                    standard.substeps, standard.velocityIterations,
                    fastestOf([&] { return runPhysdbgSolver(scene, standard, steps); })});
  if (!options.peer) return points;
  options.peer(scene, grid.peerIterations.front(), warmUpSteps);
  for (const int iterations : grid.peerIterations) {
    points.push_back({name, options.peerName, std::to_string(iterations) + " iter", 1, iterations,
                      fastestOf([&] { return options.peer(scene, iterations, steps); })});
  }
  return points;
}

std::string table(const std::vector<SolverPoint>& points) {
  std::string text = "| scene | engine | setting | ms/step | largest penetration (m) | drift (m) |\n"
                     "| --- | --- | --- | --- | --- | --- |\n";
  for (const SolverPoint& p : points) {
    text += "| " + p.scene + " | " + p.engine + " | " + p.setting + " | " + number(p.measure.msPerStep) + " | " +
            number(p.measure.largestPenetration) + " | " + number(p.measure.drift) + " |\n";
  }
  return text;
}

std::string csv(const std::vector<SolverPoint>& points) {
  std::string text = "scene,engine,substeps,iterations,ms_per_step,largest_penetration,drift\n";
  for (const SolverPoint& p : points) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%d,%d,%.6g,%.10g,%.10g\n", p.scene.c_str(), p.engine.c_str(), p.substeps,
                  p.iterations, p.measure.msPerStep, p.measure.largestPenetration, p.measure.drift);
    text += line;
  }
  return text;
}

std::string introduction(const SolverReportOptions& options, const Grid& grid) {
  std::string text = "# Solver work-precision\n\nEach scene starts at rest (boxes exactly touching, sleeping off, dt 1/60 s) "
                     "and runs " + number(grid.seconds) + " s. Largest penetration: the deepest overlap after any step "
                     "(Bullet: the deepest contact point of its manifolds after the step, found before that step's "
                     "integration). Drift: the largest distance any box's centre moved from its starting position, "
                     "at the end of the run. physdbg: one point per substeps x velocity iterations, with max_substeps "
                     "pinned to substeps (no resting-load stiffening beyond the setting), and one (physdbg default) "
                     "with the default settings, which stiffen loaded contacts and add substeps. Bullet: "
                     "btSequentialImpulseConstraintSolver, one point per btContactSolverInfo::m_numIterations, one "
                     "substep per step. ms per step of both engines are measured one after the other in this run, "
                     "each engine warmed up by an untimed run first; tiny scenes (a few hundredths of a ms per step) "
                     "are repeated (up to 5 runs under 0.2 s) and keep their fastest time.\n\n";
  if (!options.peer) text += options.peerName + ": not built (PHYSDBG_WITH_PEERS off or Bullet not found): physdbg only.\n\n";
  return text;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace

std::vector<std::pair<std::string, SceneDescription>> solverReportScenes() {
  return {{"stack10", withoutSleep(stackScene(10))},
          {"pyramid20", withoutSleep(pyramidScene(20))},
          {"mass_stack_100", withoutSleep(massStackScene({1.0, 100.0}))},
          {"mass_stack_1000", withoutSleep(massStackScene({1.0, 1000.0}))}};
}

SolverMeasure runPhysdbgSolver(SceneDescription scene, const SolverSettings& solver, int steps) {
  scene.world.solver = solver;
  World world = buildWorld(scene);
  const std::vector<Vec3> start = positionsOf(world);
  SolverMeasure measure;
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    world.step();
    measure.largestPenetration = std::max(measure.largestPenetration, world.lastStepStats().largestPenetration);
  }
  measure.msPerStep = 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() / steps;
  measure.drift = largestDisplacement(world, start);
  return measure;
}

SolverReport runSolverReport(const SolverReportOptions& options, const std::function<void(const std::string&)>& progress) {
  const Grid grid = gridFor(options.quick);
  SolverReport report;
  std::string tables;
  for (const auto& [name, scene] : solverReportScenes()) {
    if (progress) progress("solver: " + name);
    const std::vector<SolverPoint> points = runScene(name, scene, grid, options);
    tables += table(points) + "\n";
    report.points.insert(report.points.end(), points.begin(), points.end());
    if (options.outputDirectory.empty() || !options.plot) continue;
    options.plot(options.outputDirectory / (name + ".png"), name, points);
    report.plots.push_back(name + ".png");
  }
  report.markdown = introduction(options, grid) + tables;
  if (options.outputDirectory.empty()) return report;
  writeFile(options.outputDirectory / "solver.md", report.markdown);
  writeFile(options.outputDirectory / "solver.csv", csv(report.points));
  writeHtmlIndex(options.outputDirectory, "physdbg solver work-precision", report.markdown, report.plots);
  return report;
}

}  // namespace physdbg::reports
