#pragma once
// A report folder that several processes fill one case at a time: CTest runs
// each golden test in its own process, in parallel. Each process writes only
// REPORT/CASE/ (its pictures and result.json) and then rebuilds index.html
// from the result files present, so no process loses another's entry.
#include <filesystem>
#include <string>

#include "golden/html_report.h"
#include "golden/results.h"

namespace physdbg::golden {

// Writes REPORT/NAME/result.json and rebuilds the index. Returns REPORT/NAME.
std::filesystem::path recordCase(const std::filesystem::path& reportRoot, const ReportPage& page,
                                 const CaseResult& result);

// Removes REPORT/NAME (it passes now) and rebuilds the index.
void clearCase(const std::filesystem::path& reportRoot, const ReportPage& page, const std::string& caseName);

}  // namespace physdbg::golden
