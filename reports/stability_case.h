#pragma once
// One stiff or extreme scene with a stated pass criterion and the figure it
// is judged on. The same cases back `physdbg report stability` and the CTest
// tests labelled `stability`; the tests use shorter runs (RunLength::Test).
#include <functional>
#include <string>
#include <vector>

namespace physdbg::reports {

enum class RunLength { Test, Report };

struct StabilityOutcome {
  double figure = 0.0;  // the measured quantity the criterion is about
  bool pass = false;
  std::string detail;   // what else was seen (steps run, faults, ...)
};

struct StabilityCase {
  std::string name;
  std::string criterion;  // human-readable, with the threshold
  std::string unit;       // of the figure
  std::function<StabilityOutcome(RunLength)> run;
};

// Every case, in a fixed order.
std::vector<StabilityCase> stabilitySuite();

// Throws std::invalid_argument naming the unknown case.
StabilityCase findStabilityCase(const std::string& name);

}  // namespace physdbg::reports
