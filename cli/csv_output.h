#pragma once
// A CSV file a command streams row by row (--trace, --series): nothing is held
// per step, so a long run costs disk, not memory. A failed write (disk full,
// /dev/full) is a UsageError naming the option and the path, found after each
// batch of rows and at the close, not silently at exit.
#include <fstream>
#include <string>

namespace physdbg::cli {

class CsvOutput {
 public:
  // Opens `path` and writes the header line; throws naming `option`.
  CsvOutput(const std::string& option, const std::string& path, const std::string& header);

  void writeLine(const char* line) { file_ << line; }
  // Throws naming the option when a write so far failed.
  void check();
  void close();

 private:
  std::string option_, path_;
  std::ofstream file_;
};

}  // namespace physdbg::cli
