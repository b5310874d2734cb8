#pragma once
// `physdbg report accuracy`: every analytic reference swept over dt (1/30 to
// 1/3840 s) and solver settings, the contact depths over GJK/EPA tolerances.
// Writes one CSV per reference and returns a Markdown summary with the
// convergence order per method and what it means. The plots are drawn by
// whoever calls (the physdbg command, through the one plotter in viewer/):
// reports/ links no renderer, so the engine-only build keeps its reports.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "reports/accuracy_references.h"

namespace physdbg::reports {

struct AccuracySample {
  std::string reference, method;
  double parameter = 0.0;  // dt (s) or the GJK/EPA relative tolerance
  double error = 0.0;
  double milliseconds = 0.0;
  std::string note;
};

// One reference's samples, by method name (ordered: repeatable files).
using AccuracyMethods = std::map<std::string, std::vector<AccuracySample>>;

struct AccuracyOptions {
  bool quick = false;                     // 4 time steps, fewer tolerances
  std::filesystem::path outputDirectory;  // empty: no files
  // With an output directory: draws DIR/REFERENCE.png for one reference.
  std::function<void(const std::filesystem::path& png, const std::string& reference, const AccuracyMethods& methods)>
      plot;
  // The peer engine (Bullet, wired by the caller) for the references it can
  // express: drawn as one more method. Empty: the summary says it was not built.
  SimulationFactory peer;
  std::string peerName = "bullet";
};

// Errors at or below this are floating-point round-off, not a dt effect.
inline constexpr double roundOffError = 1e-10;

// The convergence order and what it means, for the summary: a number only
// when one means something. "exact" when every error is round-off;
// otherwise why no order is given (too few errors above round-off, errors
// that do not fall as dt does, or rise somewhere on the way).
struct OrderFit {
  double order;      // the least-squares slope, NaN when none is given
  std::string text;  // "2.00", "exact (...)", "none: ..."
};
OrderFit fitOrder(const std::vector<AccuracySample>& samples);

// Least-squares slope of log(error) against log(parameter), over samples
// with error above roundOffError (below that it is rounding, and the slope
// says nothing about dt). NaN with < 2 points.
double fittedOrder(const std::vector<AccuracySample>& samples);

std::vector<AccuracySample> runAccuracySweep(bool quick, const std::function<void(const std::string&)>& progress);

// The time-step references the peer can run, over the same dt values; the
// method is named after the peer ("bullet (own solver)").
std::vector<AccuracySample> runPeerAccuracySweep(bool quick, const SimulationFactory& peer, const std::string& peerName);

// Runs the sweep, writes the files and returns the Markdown summary.
std::string runAccuracyReport(const AccuracyOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace physdbg::reports
