#include "reports/stability_report.h"

#include <chrono>
#include <cstdio>

namespace physdbg::reports {
namespace {

std::string figureText(double figure) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", figure);
  return text;
}

// Commas and quotes inside a CSV field.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::vector<StabilityRow> runStabilitySuite(RunLength length, const std::string& filter,
                                            const std::function<void(const StabilityRow&)>& onRow) {
  std::vector<StabilityRow> rows;
  for (const StabilityCase& entry : stabilitySuite()) {
    if (!filter.empty() && entry.name.find(filter) == std::string::npos) continue;
    const auto start = std::chrono::steady_clock::now();
    StabilityRow row{entry.name, entry.criterion, entry.unit, entry.run(length), 0.0};
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (onRow) onRow(row);
    rows.push_back(row);
  }
  return rows;
}

std::string stabilityMarkdown(const std::vector<StabilityRow>& rows) {
  std::string text = "| case | result | figure | unit | criterion | detail |\n| --- | --- | --- | --- | --- | --- |\n";
  int passed = 0;
  for (const StabilityRow& row : rows) {
    passed += row.outcome.pass ? 1 : 0;
    text += "| " + row.name + " | " + (row.outcome.pass ? "PASS" : "**FAIL**") + " | " + figureText(row.outcome.figure) +
            " | " + row.unit + " | " + row.criterion + " | " + row.outcome.detail + " |\n";
  }
  return text + "\n" + std::to_string(passed) + " of " + std::to_string(rows.size()) + " cases pass.\n";
}

std::string stabilityCsv(const std::vector<StabilityRow>& rows) {
  std::string text = "case,pass,figure,unit,seconds,criterion,detail\n";
  for (const StabilityRow& row : rows) {
    text += row.name + "," + (row.outcome.pass ? "1" : "0") + "," + figureText(row.outcome.figure) + "," + row.unit +
            "," + figureText(row.seconds) + "," + quoted(row.criterion) + "," + quoted(row.outcome.detail) + "\n";
  }
  return text;
}

}  // namespace physdbg::reports
