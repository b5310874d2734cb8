#include "cli/csv_output.h"

#include <cerrno>

#include "cli/output_folder.h"

namespace physdbg::cli {

CsvOutput::CsvOutput(const std::string& option, const std::string& path, const std::string& header)
    : option_(option), path_(path) {
  errno = 0;
  file_.open(path);
  if (!file_) throw outputError(option_, path_);
  file_ << header << '\n';
}

void CsvOutput::check() {
  if (!file_) throw outputError(option_, path_);
  errno = 0;
}

void CsvOutput::close() {
  errno = 0;
  file_.flush();
  check();
  file_.close();
  check();
}

}  // namespace physdbg::cli
