#pragma once
// `physdbg bench --repeat N`: the same benchmarks run N times over, each run
// still timing physdbg and its peer side by side. On a shared machine one
// run's ratio can be 15% off; the run with the median ratio is a figure two
// sessions can compare. This folds the runs' records into one per case.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

namespace physdbg::bench {

// runs[r] holds the records run r printed, in order. A case is a record's
// name, n and threads, and how many records before it in its run had the
// same three (so repeated names stay apart). Each case's result is the
// record of the run with the median ratio (the lower of the two middle ones
// for an even count; by ours_ms where no peer ran), with "repeats",
// "ratio_runs" and "ours_ms_runs" (every run's, in run order), "ratio_min"
// and "ratio_max" added. Cases come in the order of their first appearance.
std::vector<nlohmann::json> medianOfRuns(const std::vector<std::vector<nlohmann::json>>& runs);

}  // namespace physdbg::bench
