// The sweep: each time-step reference once per (method, dt); each depth
// reference once per (method, tolerance), timed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "reports/accuracy_references.h"
#include "reports/accuracy_report.h"

namespace physdbg::reports {
namespace {

struct SolverMethod {
  std::string name;
  SolverSettings solver;
};

std::vector<SolverMethod> solverMethods() {
  SolverSettings seed;
  seed.kind = SolverKind::Seed;
  SolverSettings single;
  single.substeps = 1;
  SolverSettings standard;  // the default: 8 substeps x 2 sweeps, a body resting alone 4
  SolverSettings iterated;
  iterated.velocityIterations = 4;
  return {{"seed", seed},
          {"si 1 substep", single},
          {"si default", standard},
          {"si " + std::to_string(iterated.substeps) + " substeps x4 iter", iterated}};
}

template <typename Run>
double timedMilliseconds(Run&& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<int> sweepRates(bool quick) {
  return quick ? std::vector<int>{30, 60, 120, 240} : std::vector<int>{30, 60, 120, 240, 480, 960, 1920, 3840};
}

// Runs are deterministic: repeats change only the time, and the fastest is
// the least disturbed by other work on the machine.
AccuracySample timedSample(const std::string& reference, const std::string& method, const WorldSettings& settings,
                           int repeats, const std::function<ReferenceResult(const WorldSettings&)>& run) {
  AccuracySample sample{reference, method, settings.dt, 0.0, 1e300, ""};
  for (int repeat = 0; repeat < repeats; ++repeat) {
    sample.milliseconds = std::min(sample.milliseconds, timedMilliseconds([&] {
      const ReferenceResult result = run(settings);
      sample.error = result.error;
      sample.note = result.note;
    }));
  }
  return sample;
}

}  // namespace

std::vector<AccuracySample> runAccuracySweep(bool quick, const std::function<void(const std::string&)>& progress) {
  const int timingRepeats = quick ? 1 : 3;
  std::vector<AccuracySample> samples;
  for (const TimeStepReference& reference : timeStepReferences()) {
    if (progress) progress("accuracy: " + reference.name);
    for (const SolverMethod& method : solverMethods()) {
      for (const int rate : sweepRates(quick)) {
        WorldSettings settings;
        settings.dt = 1.0 / rate;
        settings.solver = method.solver;
        samples.push_back(timedSample(reference.name, method.name, settings, timingRepeats, reference.run));
      }
    }
  }
  const std::vector<double> tolerances =
      quick ? std::vector<double>{1e-2, 1e-6, 1e-12} : std::vector<double>{1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  const int repeats = quick ? 10 : 2000;  // queries take microseconds
  for (const DepthReference& reference : depthReferences()) {
    if (progress) progress("accuracy: " + reference.name);
    for (const bool closedForm : {true, false}) {
      for (const double tolerance : tolerances) {
        NarrowPhaseOptions options;
        options.analyticFastPaths = closedForm;
        options.relativeTolerance = tolerance;
        AccuracySample sample{reference.name, closedForm ? "closed form if any" : "gjk/epa", tolerance, 0.0, 0.0, ""};
        sample.milliseconds = timedMilliseconds([&] {
                                for (int i = 0; i < repeats; ++i) sample.error = reference.run(options).error;
                              }) / repeats;
        samples.push_back(sample);
      }
    }
  }
  return samples;
}

std::vector<AccuracySample> runPeerAccuracySweep(bool quick, const SimulationFactory& peer, const std::string& peerName) {
  // The first world a peer builds pays for its memory pools (Bullet: tens of
  // ms, more than a whole run): built once here, untimed.
  peer(SceneDescription{});
  std::vector<AccuracySample> samples;
  for (const TimeStepReference& reference : timeStepReferences()) {
    if (!reference.runIn) continue;
    const auto run = [&](const WorldSettings& settings) { return reference.runIn(settings, peer); };
    for (const int rate : sweepRates(quick)) {
      WorldSettings settings;
      settings.dt = 1.0 / rate;
      samples.push_back(timedSample(reference.name, peerName + " (own solver)", settings, quick ? 1 : 3, run));
    }
  }
  return samples;
}

}  // namespace physdbg::reports
