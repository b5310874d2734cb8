#pragma once
// `physdbg report solver`: work-precision of the contact solver on stiff
// scenes (10-box stack, base-20 pyramid, 100:1 and 1000:1 mass stacks with
// the heavy box on top). One point per physdbg substeps x iterations setting
// and one per Bullet iteration count: largest penetration and drift against
// ms per step, timed side by side in the same run. Bullet is reached through
// `peer`, wired by the caller (bench/ holds Bullet; reports/ links neither it
// nor the renderer), and plots are drawn by the caller's `plot`.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace physdbg::reports {

// What one run of a scene measured.
struct SolverMeasure {
  double msPerStep = 0.0;
  double largestPenetration = 0.0;  // m: the deepest overlap seen after any step
  double drift = 0.0;  // m: the largest distance a body's centre moved from its start (its rest position)
};

struct SolverPoint {
  std::string scene, engine, setting;  // engine: "physdbg", "physdbg default" or the peer's name
  int substeps = 1, iterations = 1;
  SolverMeasure measure;
};

// Runs `scene` (dt, gravity, bodies) for `steps` steps with `iterations`
// solver iterations and measures it. Empty when the peer is not built.
using PeerSolverRun = std::function<SolverMeasure(const SceneDescription& scene, int iterations, int steps)>;

struct SolverReportOptions {
  bool quick = false;                     // shorter runs, fewer settings: a few seconds
  std::filesystem::path outputDirectory;  // empty: no files
  PeerSolverRun peer;                     // empty: "Bullet was not built"
  std::string peerName = "bullet";
  std::function<void(const std::filesystem::path& png, const std::string& scene, const std::vector<SolverPoint>& points)>
      plot;
};

struct SolverReport {
  std::vector<SolverPoint> points;
  std::string markdown;
  std::vector<std::string> plots;  // file names written into the output directory
};

// The scenes, by name, as the report runs them (sleeping off).
std::vector<std::pair<std::string, SceneDescription>> solverReportScenes();

// The scene in physdbg under `solver`, measured.
SolverMeasure runPhysdbgSolver(SceneDescription scene, const SolverSettings& solver, int steps);

SolverReport runSolverReport(const SolverReportOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace physdbg::reports
