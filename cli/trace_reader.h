#pragma once
// A trace written by `simulate --trace` (step,time,body,x,...), read row by
// row through NumericCsv's bounds, plus what a trace must be: `step` and
// `body` columns of whole numbers, rows in the order simulate writes them
// (steps ascending, bodies ascending within a step), at most maxTraceRows.
#include <string>
#include <vector>

#include "cli/numeric_csv.h"

namespace physdbg::cli {

inline constexpr long long maxTraceRows = 100'000'000;

struct TraceRow {
  long long line = 0;  // 1-based line number in the file
  long long step = 0, body = 0;
  std::vector<double> values;  // one per column, in header order (step and body included)
};

class TraceReader {
 public:
  explicit TraceReader(const std::string& path);

  const std::string& path() const { return csv_.path(); }
  const std::vector<std::string>& columns() const { return csv_.columns(); }
  int columnIndex(const std::string& name) const { return csv_.columnIndex(name); }

  // The next row, false at the end.
  bool next(TraceRow& row);

 private:
  long long wholeNumber(const TraceRow& row, std::size_t column) const;

  NumericCsv csv_;
  std::size_t stepColumn_ = 0, bodyColumn_ = 0;
  long long rows_ = 0, lastStep_ = -1, lastBody_ = -1;
};

}  // namespace physdbg::cli
