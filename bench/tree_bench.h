#pragma once
// `physdbg bench tree`: quality and speed of the broad-phase tree against
// Bullet's btDbvt, measured in the same run on the same boxes.
#include "bench/bench.h"

namespace physdbg::bench {

void runTreeBenchmark(const BenchOptions& options, const BenchSink& sink);

// The cases, one file each.
void runTilesCase(const BenchOptions& options, const BenchSink& sink);
void runMovingCase(const BenchOptions& options, const BenchSink& sink);
void runInsertRemoveCase(const BenchOptions& options, const BenchSink& sink);

}  // namespace physdbg::bench
