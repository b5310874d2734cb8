#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <vector>

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

// The sleepers never meet the spheres: physdbg's spheres end bit for bit
// where they end alone, and no sleeper moves (Bullet's likewise, to 0.1 mm).
TEST(Benchmarks, SleepingBenchmarkDoesTheSameWorkWithAndWithoutSleepers) {
  for (const Benchmark& benchmark : allBenchmarks()) {
    if (benchmark.name != "sleeping") continue;
    BenchOptions options;
    options.quick = true;
    options.threads = 1;
    int records = 0;
    benchmark.run(options, [&](const nlohmann::json& record) {
      ++records;
      EXPECT_EQ(record.at("ours_sphere_mismatch").get<double>(), 0.0) << record.dump();
      EXPECT_EQ(record.at("ours_largest_prop_move").get<double>(), 0.0) << record.dump();
      EXPECT_TRUE(record.at("same_work").get<bool>()) << record.dump();
      EXPECT_GT(record.at("ours_bytes_per_body").get<double>(), 0.0) << record.dump();
    });
    EXPECT_EQ(records, 1);
  }
}

// The scene benchmarks run one thread and every core (one row each, the
// all-core one with its scaling and the host's), or only what --threads
// asks for.
TEST(Benchmarks, SceneBenchmarksReportTheirThreads) {
  for (const Benchmark& benchmark : allBenchmarks()) {
    if (benchmark.name != "drop" && benchmark.name != "pyramid" && benchmark.name != "jolt_pyramid") continue;
    SCOPED_TRACE(benchmark.name);
    BenchOptions options;
    options.quick = true;
    std::vector<int> threads;
    benchmark.run(options, [&](const nlohmann::json& record) {
      threads.push_back(record.at("threads").get<int>());
      EXPECT_EQ(record.contains("scaling"), threads.back() > 1) << record.dump();
      EXPECT_EQ(record.contains("host_scaling"), threads.back() > 1) << record.dump();
      if (record.contains("host_scaling")) EXPECT_GT(record["host_scaling"].get<double>(), 0.0) << record.dump();
      // Where physdbg's step time went, stage by stage, adding up to the step.
      const nlohmann::json& stages = record.at("ours_stage_ms");
      double staged = 0.0;
      for (const char* name :
           {"forces", "broad_phase", "pairs", "narrow_phase", "manifolds", "solver", "after_solve", "other"})
        staged += stages.at(name).get<double>();
      EXPECT_NEAR(staged, stages.at("total").get<double>(), 1e-9) << record.dump();
      EXPECT_LE(stages.at("solver_islands").get<double>(), stages.at("solver").get<double>()) << record.dump();
      EXPECT_LE(stages.at("total").get<double>(), record.at("ours_ms").get<double>()) << record.dump();
    });
    ASSERT_FALSE(threads.empty());
    EXPECT_EQ(threads.front(), 1);
    options.threads = 3;
    benchmark.run(options, [&](const nlohmann::json& record) { EXPECT_EQ(record.at("threads"), 3) << record.dump(); });
  }
}

}  // namespace
}  // namespace physdbg::bench
