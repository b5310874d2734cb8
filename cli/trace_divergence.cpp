#include "cli/trace_divergence.h"

#include <cmath>
#include <cstdio>

namespace physdbg::cli {
namespace {

// Column index in each trace of a column both have (step and body excluded:
// they say where, they are not compared).
struct SharedColumn {
  std::string name;
  std::size_t first, second;
};

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string where(const TraceRow& row) {
  return "step " + std::to_string(row.step) + " body " + std::to_string(row.body);
}

std::vector<SharedColumn> sharedColumns(const TraceReader& first, const TraceReader& second, Divergence& result) {
  std::vector<SharedColumn> shared;
  for (std::size_t i = 0; i < first.columns().size(); ++i) {
    const std::string& name = first.columns()[i];
    const int other = second.columnIndex(name);
    if (other < 0) result.lines.push_back("column '" + name + "' is only in " + first.path());
    else if (name != "step" && name != "body") shared.push_back({name, i, static_cast<std::size_t>(other)});
  }
  for (const std::string& name : second.columns())
    if (first.columnIndex(name) < 0) result.lines.push_back("column '" + name + "' is only in " + second.path());
  if (!result.lines.empty()) result.kind = Divergence::Kind::Shape;
  return shared;
}

// One trace ended: the other's next row is the first it lacks.
void endedEarly(const TraceReader& ended, const TraceReader& other, const TraceRow& row, Divergence& result) {
  result.kind = Divergence::Kind::Shape;
  result.step = row.step;
  result.body = row.body;
  result.lines.push_back(ended.path() + " ends before " + where(row) + ", which " + other.path() + " has (line " +
                         std::to_string(row.line) + ")");
}

// The row with the smaller (step, body) is the one the other trace lacks.
void missingRow(const TraceReader& first, const TraceRow& a, const TraceReader& second, const TraceRow& b,
                Divergence& result) {
  const bool firstHasIt = a.step < b.step || (a.step == b.step && a.body < b.body);
  const TraceRow& present = firstHasIt ? a : b;
  const TraceRow& next = firstHasIt ? b : a;
  result.kind = Divergence::Kind::Shape;
  result.step = present.step;
  result.body = present.body;
  result.lines.push_back(where(present) + " is in " + (firstHasIt ? first : second).path() + " (line " +
                         std::to_string(present.line) + ") but not in " + (firstHasIt ? second : first).path() +
                         " (its line " + std::to_string(next.line) + " is " + where(next) + ")");
}

// The first shared column of the row that differs by more than `tolerance`.
bool valueDiffers(const TraceReader& first, const TraceRow& a, const TraceReader& second, const TraceRow& b,
                  const std::vector<SharedColumn>& columns, double tolerance, Divergence& result) {
  for (const SharedColumn& column : columns) {
    const double x = a.values[column.first], y = b.values[column.second];
    if (!(std::abs(x - y) > tolerance)) continue;
    result.kind = Divergence::Kind::Value;
    result.step = a.step;
    result.body = a.body;
    result.field = column.name;
    result.lines.insert(result.lines.begin(), "traces differ at " + where(a) + ", field " + column.name);
    result.lines.push_back("  " + first.path() + " line " + std::to_string(a.line) + ": " + number(x));
    result.lines.push_back("  " + second.path() + " line " + std::to_string(b.line) + ": " + number(y));
    result.lines.push_back("  |difference| " + number(std::abs(x - y)) + " > tolerance " + number(tolerance));
    return true;
  }
  return false;
}

}  // namespace

Divergence findDivergence(TraceReader& first, TraceReader& second, double tolerance) {
  Divergence result;
  const std::vector<SharedColumn> columns = sharedColumns(first, second, result);
  TraceRow a, b;
  long long rows = 0;
  while (true) {
    const bool hasFirst = first.next(a), hasSecond = second.next(b);
    if (!hasFirst && !hasSecond) break;
    if (!hasFirst || !hasSecond) {
      if (hasFirst) endedEarly(second, first, a, result);
      else endedEarly(first, second, b, result);
      return result;
    }
    if (a.step != b.step || a.body != b.body) {
      missingRow(first, a, second, b, result);
      return result;
    }
    if (valueDiffers(first, a, second, b, columns, tolerance, result)) return result;
    ++rows;
  }
  if (result.kind == Divergence::Kind::Agree)
    result.lines.push_back("traces agree: " + std::to_string(rows) + " rows, every value within tolerance " +
                           number(tolerance));
  else
    result.lines.push_back("the " + std::to_string(columns.size()) + " columns both have agree in all " +
                           std::to_string(rows) + " rows, within tolerance " + number(tolerance));
  return result;
}

}  // namespace physdbg::cli
