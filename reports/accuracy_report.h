#pragma once
// `physdbg report accuracy`: every analytic reference swept over dt (1/30 to
// 1/3840 s) and solver settings, the contact depths over GJK/EPA tolerances.
// Writes one CSV per reference, a work-precision plot per reference (gnuplot,
// when installed), and returns a Markdown summary with the fitted
// convergence order per method.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace physdbg::reports {

struct AccuracyOptions {
  bool quick = false;                     // 4 time steps, fewer tolerances
  std::filesystem::path outputDirectory;  // empty: no files
};

struct AccuracySample {
  std::string reference, method;
  double parameter = 0.0;  // dt (s) or the GJK/EPA relative tolerance
  double error = 0.0;
  double milliseconds = 0.0;
  std::string note;
};

// Least-squares slope of log(error) against log(parameter), over samples
// with error above 1e-10 (below that it is rounding, and the slope says
// nothing about dt). NaN with < 2 points.
double fittedOrder(const std::vector<AccuracySample>& samples);

std::vector<AccuracySample> runAccuracySweep(bool quick, const std::function<void(const std::string&)>& progress);

// Runs the sweep, writes the files and returns the Markdown summary.
std::string runAccuracyReport(const AccuracyOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace physdbg::reports
