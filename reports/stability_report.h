#pragma once
// The stability suite as a table: one row per case, PASS/FAIL with the figure.
#include <functional>
#include <string>
#include <vector>

#include "reports/stability_case.h"

namespace physdbg::reports {

struct StabilityRow {
  std::string name, criterion, unit;
  StabilityOutcome outcome;
  double seconds = 0.0;  // wall time of the case
};

// Runs every case whose name contains `filter` (all when empty), calling
// `onRow` as each one finishes.
std::vector<StabilityRow> runStabilitySuite(RunLength length, const std::string& filter,
                                            const std::function<void(const StabilityRow&)>& onRow);

std::string stabilityMarkdown(const std::vector<StabilityRow>& rows);
std::string stabilityCsv(const std::vector<StabilityRow>& rows);

}  // namespace physdbg::reports
