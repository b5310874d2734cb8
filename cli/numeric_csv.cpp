#include "cli/numeric_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "cli/arguments.h"

namespace physdbg::cli {

std::vector<std::string> splitFields(const std::string& line, std::size_t maxFields) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (fields.size() < maxFields) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

NumericCsv::NumericCsv(const std::string& path) : path_(path), file_(path, std::ios::binary) {
  if (!file_) throw UsageError("cannot read '" + path + "'");
  std::string header;
  if (!readLine(header)) fail("empty file, expected a header line of column names");
  columns_ = splitFields(header, maxCsvColumns + 1);
  if (columns_.size() > maxCsvColumns) fail("more than " + std::to_string(maxCsvColumns) + " columns in the header");
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const auto begin = columns_.begin(), self = begin + static_cast<long>(i);
    if (columns_[i].empty()) failColumn(i, "empty column name");
    if (std::find(begin, self, columns_[i]) != self) failColumn(i, "column named twice");
  }
}

int NumericCsv::columnIndex(const std::string& name) const {
  const auto found = std::find(columns_.begin(), columns_.end(), name);
  return found == columns_.end() ? -1 : static_cast<int>(found - columns_.begin());
}

// One line of at most maxCsvLineLength characters, without its "\n" or
// "\r\n"; false at the end of the file.
bool NumericCsv::readLine(std::string& line) {
  line.clear();
  std::streambuf& buffer = *file_.rdbuf();
  int c = buffer.sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  ++line_;
  for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer.sbumpc()) {
    if (line.size() == maxCsvLineLength) fail("line longer than " + std::to_string(maxCsvLineLength) + " characters");
    line.push_back(static_cast<char>(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

bool NumericCsv::next(std::vector<double>& values) {
  std::string line;
  if (!readLine(line)) return false;
  const std::vector<std::string> fields = splitFields(line, columns_.size() + 1);
  if (fields.size() != columns_.size())
    fail(std::string(fields.size() > columns_.size() ? "more" : "fewer") + " fields than the header's " +
         std::to_string(columns_.size()) + " columns");
  values.resize(columns_.size());
  for (std::size_t i = 0; i < fields.size(); ++i) values[i] = parseValue(fields[i], i);
  return true;
}

double NumericCsv::parseValue(const std::string& field, std::size_t column) const {
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  std::string shown = "'";
  shown.append(field, 0, 40).append(field.size() > 40 ? "...'" : "'");
  if (field.empty() || error != std::errc() || end != field.data() + field.size())
    failColumn(column, shown + " is not a number");
  if (!std::isfinite(value))
    failColumn(column, shown + " is not finite (the run had already failed there; compare or plot the rows before)");
  return value;
}

void NumericCsv::fail(const std::string& what) const {
  throw UsageError(path_ + ":" + std::to_string(line_) + ": " + what);
}

void NumericCsv::failColumn(std::size_t column, const std::string& what) const {
  fail("column " + std::to_string(column + 1) + " ('" + columns_[column].substr(0, 40) + "'): " + what);
}

}  // namespace physdbg::cli
