#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bench/bench.h"

namespace physdbg::bench {
namespace {

// Runs each benchmark in quick mode and checks every record carries the
// fields the README promises. Times are not checked: they are noise here.
TEST(Benchmarks, EveryBenchmarkPrintsTheCommonFields) {
  for (const Benchmark& benchmark : allBenchmarks()) {
    SCOPED_TRACE(benchmark.name);
    int records = 0;
    BenchOptions options;
    options.quick = true;
    benchmark.run(options, [&](const nlohmann::json& record) {
      ++records;
      for (const char* key : {"name", "n", "ours_ms", "peer", "peer_ms", "ratio"}) {
        EXPECT_TRUE(record.contains(key)) << key << " missing in " << record.dump();
      }
      EXPECT_GT(record["ours_ms"].get<double>(), 0.0) << record.dump();
    });
    EXPECT_GT(records, 0);
  }
}

}  // namespace
}  // namespace physdbg::bench
