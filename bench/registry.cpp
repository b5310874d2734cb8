#include "bench/bench.h"

namespace physdbg::bench {

// Each benchmark lives in its own file and is listed here, in output order.
std::vector<Benchmark> allBenchmarks() {
  std::vector<Benchmark> benchmarks;
  return benchmarks;
}

}  // namespace physdbg::bench
