#pragma once
// Where two traces of `simulate --trace` part: the first step, body and field
// whose values differ by more than a tolerance, or the first place their
// shapes differ (a step or body only one has, one ending early). The traces
// are read in lockstep, so two long runs cost no memory.
#include <optional>
#include <string>
#include <vector>

#include "cli/trace_reader.h"

namespace physdbg::cli {

struct Divergence {
  enum class Kind { Agree, Value, Shape };
  Kind kind = Kind::Agree;
  // Where (Value, and Shape when one trace has a row the other lacks).
  std::optional<long long> step, body;
  std::string field;
  // What to print: one line per fact, naming the files and their lines.
  std::vector<std::string> lines;
};

// Columns only one trace has are listed in `lines` (and make the traces
// differ); the values of the common ones are still compared.
// Absolute tolerance: a value differs when |a - b| > tolerance.
Divergence findDivergence(TraceReader& first, TraceReader& second, double tolerance);

}  // namespace physdbg::cli
