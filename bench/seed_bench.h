#pragma once
#include "bench/bench.h"

namespace physdbg::bench {

// Step time of each of the design's scenes (scenes/design_scenes.h), so its
// claims (tree about 4x faster than brute force at 48 balls, twice the
// bodies twice the time) can be set against this engine's figures.
void runSeedBenchmark(const BenchOptions& options, const BenchSink& sink);

}  // namespace physdbg::bench
