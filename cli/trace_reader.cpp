#include "cli/trace_reader.h"

#include <cmath>

namespace physdbg::cli {

TraceReader::TraceReader(const std::string& path) : csv_(path) {
  if (csv_.columnIndex("step") < 0 || csv_.columnIndex("body") < 0)
    csv_.fail("a trace (simulate --trace) has 'step' and 'body' columns; this header has neither or one");
  stepColumn_ = static_cast<std::size_t>(csv_.columnIndex("step"));
  bodyColumn_ = static_cast<std::size_t>(csv_.columnIndex("body"));
}

// Below 2^53 every whole number is exact in a double.
long long TraceReader::wholeNumber(const TraceRow& row, std::size_t column) const {
  const double value = row.values[column];
  if (value < 0 || value > 9.0e15 || value != std::floor(value))
    csv_.failColumn(column, "expected a whole number >= 0");
  return static_cast<long long>(value);
}

bool TraceReader::next(TraceRow& row) {
  if (!csv_.next(row.values)) return false;
  if (++rows_ > maxTraceRows) csv_.fail("more than " + std::to_string(maxTraceRows) + " rows");
  row.line = csv_.line();
  row.step = wholeNumber(row, stepColumn_);
  row.body = wholeNumber(row, bodyColumn_);
  if (row.step < lastStep_ || (row.step == lastStep_ && row.body <= lastBody_))
    csv_.fail("step " + std::to_string(row.step) + " body " + std::to_string(row.body) + " comes after step " +
              std::to_string(lastStep_) + " body " + std::to_string(lastBody_) +
              " (simulate writes steps, then bodies, in ascending order, each once)");
  lastStep_ = row.step;
  lastBody_ = row.body;
  return true;
}

}  // namespace physdbg::cli
