#pragma once
// Analytic references for the accuracy report. Each reference builds its
// scene with the given world settings (dt and solver included), runs it and
// returns its error against the closed form.
#include <functional>
#include <string>
#include <vector>

#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/world.h"

namespace physdbg::reports {

struct ReferenceResult {
  double error = 0.0;
  std::string note;  // e.g. whether the tumbling box flipped
};

struct TimeStepReference {
  std::string name;
  std::string expectation;  // the closed form, for the summary
  std::function<ReferenceResult(const WorldSettings&)> run;
};

std::vector<TimeStepReference> timeStepReferences();

struct DepthReference {
  std::string name;
  std::string expectation;
  std::function<ReferenceResult(const NarrowPhaseOptions&)> run;
};

std::vector<DepthReference> depthReferences();

}  // namespace physdbg::reports
