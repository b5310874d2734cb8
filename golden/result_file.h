#pragma once
// A case result as a JSON file: how a case checked by another process (GNU
// parallel, possibly on another machine) hands its verdict to the process
// that writes the report, and how the golden tests' report folder remembers
// the cases of earlier test processes.
#include <filesystem>
#include <vector>

#include "golden/results.h"

namespace physdbg::golden {

// Throws std::runtime_error when the file cannot be written.
void writeResultFile(const std::filesystem::path& path, const std::vector<CaseResult>& results);
// Throws std::runtime_error naming the file when it is missing or malformed.
std::vector<CaseResult> readResultFile(const std::filesystem::path& path);

}  // namespace physdbg::golden
