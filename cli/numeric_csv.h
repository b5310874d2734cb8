#pragma once
// A CSV file of numbers with a header line (simulate's --trace and --series),
// read row by row. Such files come from other people, so nothing the file
// sizes is allocated unchecked: a line is at most maxCsvLineLength characters
// and maxCsvColumns fields; numbers must be finite (a "nan" is a run that had
// already failed, not a value to compare or plot). Anything else is a
// UsageError (exit 2) naming the file, the line and the column.
#include <fstream>
#include <string>
#include <vector>

namespace physdbg::cli {

inline constexpr std::size_t maxCsvLineLength = 4096;
inline constexpr std::size_t maxCsvColumns = 64;

class NumericCsv {
 public:
  // Opens the file and reads its header of distinct, non-empty names.
  explicit NumericCsv(const std::string& path);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  // Index of `name` among the columns, or -1.
  int columnIndex(const std::string& name) const;
  // Line number of the row last read (the header is line 1).
  long long line() const { return line_; }

  // The next row's values, one per column; false at the end of the file.
  bool next(std::vector<double>& values);

  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void failColumn(std::size_t column, const std::string& what) const;

 private:
  bool readLine(std::string& line);
  double parseValue(const std::string& field, std::size_t column) const;

  std::string path_;
  std::ifstream file_;
  std::vector<std::string> columns_;
  long long line_ = 0;
};

// "a,b,,c" -> {"a","b","","c"}: at most maxFields, so a caller sees that a
// line had more without holding them.
std::vector<std::string> splitFields(const std::string& line, std::size_t maxFields);

}  // namespace physdbg::cli
