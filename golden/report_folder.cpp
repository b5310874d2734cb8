#include "golden/report_folder.h"

#include <algorithm>

#include "golden/result_file.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;

constexpr char kResultFile[] = "result.json";

std::vector<CaseResult> recordedCases(const fs::path& reportRoot) {
  std::vector<fs::path> files;
  if (fs::is_directory(reportRoot))
    for (const fs::directory_entry& entry : fs::directory_iterator(reportRoot))
      if (entry.is_directory() && fs::exists(entry.path() / kResultFile)) files.push_back(entry.path() / kResultFile);
  std::sort(files.begin(), files.end());
  std::vector<CaseResult> results;
  for (const fs::path& file : files)
    for (CaseResult& result : readResultFile(file)) results.push_back(std::move(result));
  return results;
}

}  // namespace

fs::path recordCase(const fs::path& reportRoot, const ReportPage& page, const CaseResult& result) {
  const fs::path folder = reportRoot / result.name;
  fs::create_directories(folder);
  writeResultFile(folder / kResultFile, {result});
  writeHtmlReport(reportRoot, page, recordedCases(reportRoot));
  return folder;
}

void clearCase(const fs::path& reportRoot, const ReportPage& page, const std::string& caseName) {
  if (!fs::exists(reportRoot / caseName)) return;
  fs::remove_all(reportRoot / caseName);
  writeHtmlReport(reportRoot, page, recordedCases(reportRoot));
}

}  // namespace physdbg::golden
