#include "cli/numerical_faults.h"

#include <cstdio>

namespace physdbg::cli {

int reportNumericalFaults(const std::string& command, const World& world) {
  for (const NumericalFault& fault : world.numericalFaults())
    std::fprintf(stderr, "physdbg %s: body %u: %s at step %d; body frozen\n", command.c_str(), fault.body,
                 fault.what.c_str(), fault.step);
  return world.numericalFaults().empty() ? 0 : 1;
}

}  // namespace physdbg::cli
