#include <stdexcept>

#include "reports/stability_case.h"
#include "reports/stability_cases.h"

namespace physdbg::reports {

std::vector<StabilityCase> stabilitySuite() {
  std::vector<StabilityCase> suite;
  for (auto group : {stackingCases(), impactCases(), shapeCases()}) {
    for (auto& entry : group) suite.push_back(std::move(entry));
  }
  return suite;
}

StabilityCase findStabilityCase(const std::string& name) {
  for (StabilityCase& entry : stabilitySuite()) {
    if (entry.name == name) return entry;
  }
  throw std::invalid_argument("unknown stability case '" + name + "'");
}

}  // namespace physdbg::reports
