#pragma once
// The golden report a person opens after a failure: REPORT/index.html with a
// table of every case (passed, failed, skipped: a skipped case compared
// nothing, and says why), and for each failed frame the expected, actual and
// diff pictures side by side, a flicker view (expected and actual taking
// turns) and a slider (actual left of the handle, expected right), because a
// one-pixel shift is easier to see moving than side by side.
#include <filesystem>
#include <string>
#include <vector>

#include "golden/results.h"

namespace physdbg::golden {

struct ReportPage {
  std::string title;
  std::string hint;  // what to run after an intended change
  bool failuresOnly = false;  // the golden tests record failures only: no pass count to show
};

// Writes REPORT/index.html through a temporary file and a rename, so a reader
// never sees half a page. Picture paths are the frames' `images` folders,
// relative to REPORT. Throws std::runtime_error when it cannot be written.
void writeHtmlReport(const std::filesystem::path& reportRoot, const ReportPage& page,
                     const std::vector<CaseResult>& results);

std::filesystem::path reportIndex(const std::filesystem::path& reportRoot);

}  // namespace physdbg::golden
