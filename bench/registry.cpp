#include "bench/bench.h"
#include "bench/seed_bench.h"
#include "bench/tree_bench.h"

namespace physdbg::bench {

Benchmark narrowBenchmark();
#ifdef PHYSDBG_HAVE_RENDER
Benchmark renderBenchmark();
Benchmark gpuBenchmark();
#endif
Benchmark dropBenchmark();
Benchmark pyramidBenchmark();
Benchmark sleepingBenchmark();
Benchmark joltPyramidBenchmark();
Benchmark memoryBenchmark();
Benchmark meshBenchmark();

// Each benchmark lives in its own file and is listed here, in output order.
std::vector<Benchmark> allBenchmarks() {
  std::vector<Benchmark> benchmarks;
  benchmarks.push_back({"tree", "broad-phase tree quality and speed against Bullet's btDbvt", runTreeBenchmark});
  benchmarks.push_back(narrowBenchmark());
  benchmarks.push_back({"seed", "the design's experiment: its scenes with its response and ours, against its figures",
                        runSeedBenchmark});
#ifdef PHYSDBG_HAVE_RENDER
  benchmarks.push_back(renderBenchmark());
#endif
  benchmarks.push_back(dropBenchmark());
  benchmarks.push_back(pyramidBenchmark());
  benchmarks.push_back(joltPyramidBenchmark());
  benchmarks.push_back(sleepingBenchmark());
  benchmarks.push_back(meshBenchmark());
  benchmarks.push_back(memoryBenchmark());
#ifdef PHYSDBG_HAVE_RENDER
  benchmarks.push_back(gpuBenchmark());
#endif
  return benchmarks;
}

}  // namespace physdbg::bench
