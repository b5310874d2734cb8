#pragma once
// The end of every command that runs a scene (simulate, render, record): a
// body whose state became NaN or Inf was frozen by the world and the run went
// on; here each one is named with its step, and the exit code says the run
// failed. One function, so every command reports faults the same way.
#include <string>

#include "engine/world.h"

namespace physdbg::cli {

// Prints "physdbg COMMAND: body N: WHAT at step S; body frozen" to stderr for
// each fault; returns 1 when there was any, else 0.
int reportNumericalFaults(const std::string& command, const World& world);

}  // namespace physdbg::cli
