#pragma once
// Runs one stability case in its short (test) form. A case the engine is
// known to fail is skipped with the diagnosis, so CI keeps running it and
// the report keeps printing FAIL with the figure.
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "reports/stability_case.h"

namespace physdbg::reports {

// name -> why the engine fails it today (see the report of issue 9). Empty:
// every case passes; a case added here is skipped with its diagnosis.
inline const std::map<std::string, std::string>& knownEngineFailures() {
  static const std::map<std::string, std::string> failures = {};
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
