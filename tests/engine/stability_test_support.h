#pragma once
// Runs one stability case in its short (test) form. A case the engine is
// known to fail is skipped with the diagnosis, so CI keeps running it and
// the report keeps printing FAIL with the figure.
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "reports/stability_case.h"

namespace physdbg::reports {

// name -> why the engine fails it today (see the report of issue 9).
inline const std::map<std::string, std::string>& knownEngineFailures() {
  static const std::map<std::string, std::string> failures = {
      {"tall_stack",
       "20-box stack never sleeps (jitter above 0.05 m/s) and creeps sideways in -x at about 4 cm/s; resting overlap "
       "13-17 mm, 3x the slop, with 4 substeps x 1 iteration"},
      {"mass_ratio_100", "soft contacts (30 Hz on the light body's effective mass) yield under a 100x load"},
      {"mass_ratio_1000",
       "soft contacts yield under a 1000x load: the light box is pushed 0.5 m into the floor within 0.5 s; 8 "
       "iterations do not help"},
      {"large_dt",
       "at dt = 1/15 s (substep 1/60 s) the 30 Hz contact spring lets the stack compress 4-8 cm per contact and "
       "creep 1 cm per step sideways until it topples"},
      {"tiny_bodies",
       "a 30 Hz contact spring sags g / (2 pi 30)^2 = 0.28 mm per contact whatever the size: 6% of a 5 mm cube per "
       "level, and the stack creeps sideways"},
  };
  return failures;
}

inline void expectStable(const std::string& name) {
  const StabilityCase entry = findStabilityCase(name);
  const StabilityOutcome outcome = entry.run(RunLength::Test);
  const auto known = knownEngineFailures().find(name);
  if (known != knownEngineFailures().end() && !outcome.pass) {
    GTEST_SKIP() << "engine: " << known->second << " (figure " << outcome.figure << " " << entry.unit << "; "
                 << outcome.detail << ")";
  }
  EXPECT_TRUE(outcome.pass) << entry.criterion << "\nfigure " << outcome.figure << " " << entry.unit << "; "
                            << outcome.detail;
}

}  // namespace physdbg::reports
