#pragma once
// `golden check -j N`: each case in a physdbg process of its own, started by
// GNU parallel (one machine, or several with --sshloginfile), each writing
// its verdict to a result file that this process gathers into one report.
// parallel gets an argument vector (reports/child_process.h) and --quote, so
// no shell ever reads the manifest path or a case name as a command.
#include <filesystem>
#include <string>
#include <vector>

#include "golden/results.h"

namespace physdbg::cli {

struct ParallelCheck {
  std::filesystem::path manifest;
  std::vector<std::string> cases;  // names, already checked against the manifest
  int jobs = 1;
  std::string sshLoginFile;  // empty: this machine only
  std::string reportDir;     // empty: no pictures
};

// Throws UsageError when GNU parallel is not installed. A case whose process
// left no result (it crashed, or a remote machine could not run it) fails,
// with a message saying how to run it alone.
std::vector<golden::CaseResult> checkThroughParallel(const ParallelCheck& check);

}  // namespace physdbg::cli
