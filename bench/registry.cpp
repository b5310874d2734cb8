#include "bench/bench.h"
#include "bench/tree_bench.h"

namespace physdbg::bench {

// Each benchmark lives in its own file and is listed here, in output order.
std::vector<Benchmark> allBenchmarks() {
  std::vector<Benchmark> benchmarks;
  benchmarks.push_back({"tree", "broad-phase tree quality and speed against Bullet's btDbvt", runTreeBenchmark});
  return benchmarks;
}

}  // namespace physdbg::bench
