#pragma once
// The stability cases, grouped by theme; stabilitySuite() lists them all.
#include <vector>

#include "reports/stability_case.h"

namespace physdbg::reports {

std::vector<StabilityCase> stackingCases();
std::vector<StabilityCase> impactCases();
std::vector<StabilityCase> shapeCases();

}  // namespace physdbg::reports
