// `physdbg bench seed` (bench/seed_bench.h) in quick mode: every design scene
// under both solvers, the design's figures beside ours, and stage shares of
// the whole step. Times are noise here; the structure and arithmetic are not.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/seed_bench.h"

namespace physdbg::bench {
namespace {

std::map<std::string, nlohmann::json> quickRows() {
  std::map<std::string, nlohmann::json> rows;
  BenchOptions options;
  options.quick = true;
  runSeedBenchmark(options, [&](const nlohmann::json& record) {
    const std::string name = record["name"].get<std::string>();
    EXPECT_EQ(rows.count(name), 0u) << "two rows named " << name;
    rows[name] = record;
  });
  return rows;
}

TEST(SeedBench, RunsEveryDesignSceneUnderBothSolvers) {
  const auto rows = quickRows();
  for (const char* scene : {"balls24", "balls48", "balls48_bruteforce", "balls48_no_static_skip",
                            "balls48_bruteforce_no_static_skip", "bounce"})
    for (const char* solver : {"seed", "sequential_impulse"}) {
      const std::string name = std::string(scene) + "/" + solver;
      ASSERT_EQ(rows.count(name), 1u) << name;
      EXPECT_EQ(rows.at(name)["solver"], solver);
    }
  // Brute force doubles the narrow-phase tests of each candidate pair it keeps.
  EXPECT_GT(rows.at("balls48_bruteforce/seed")["narrow_tests"].get<double>(),
            rows.at("balls48/seed")["narrow_tests"].get<double>());
}

TEST(SeedBench, SetsTheDesignsFiguresBesideOurs) {
  const auto rows = quickRows();
  EXPECT_EQ(rows.at("balls24/seed vs design fps")["design_fps"], 300.0);
  EXPECT_EQ(rows.at("balls48/seed vs design fps")["design_fps"], 150.0);
  EXPECT_NEAR(rows.at("balls48/seed vs design fps")["peer_ms"].get<double>(), 1000.0 / 150.0, 1e-12);
  const auto expectRatio = [&](const std::string& scene, double design) {
    SCOPED_TRACE(scene);
    const nlohmann::json& row = rows.at(scene + "/seed");
    const nlohmann::json& vs = rows.at(scene + "/seed vs design ratio");
    EXPECT_NEAR(vs["design_ratio"].get<double>(), design, 1e-3);
    EXPECT_DOUBLE_EQ(vs["our_ratio"].get<double>(), row["ratio"].get<double>());
    EXPECT_NEAR(vs["ratio"].get<double>(), row["ratio"].get<double>() / design, 1e-9);
  };
  expectRatio("balls48", 2.0);
  expectRatio("balls48_bruteforce", 515.0 / 130.0);
  expectRatio("balls48_no_static_skip", 600.0 / 515.0);
  expectRatio("balls48_bruteforce_no_static_skip", 515.0 / 130.0);
}

TEST(SeedBench, StageSharesOfTheStepAddUpToOne) {
  const auto rows = quickRows();
  for (const char* scene : {"balls48/seed", "balls48_bruteforce/seed"}) {
    SCOPED_TRACE(scene);
    double sum = 0.0;
    for (const char* stage : {"broad", "narrow", "solver", "other"})
      sum += rows.at(std::string(scene) + " " + stage)["fraction"].get<double>();
    // "other" is what the replayed stages leave of the step, never below 0.
    EXPECT_GE(sum, 1.0 - 1e-9);
  }
}

}  // namespace
}  // namespace physdbg::bench
