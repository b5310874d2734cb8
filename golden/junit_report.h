#pragma once
// Golden results as JUnit XML, the format CI servers (GitLab, Jenkins, GitHub
// test reporters) show: one <testcase> per frame, classname the case,
// <failure> with the comparison's figures, <skipped/> when the renderer key
// has no approved frames (a CI page must not count it as passed).
#include <filesystem>
#include <string>
#include <vector>

#include "golden/results.h"

namespace physdbg::golden {

// Throws std::runtime_error when the file cannot be written.
void writeJunitReport(const std::filesystem::path& path, const std::string& suiteName,
                      const std::vector<CaseResult>& results);

}  // namespace physdbg::golden
