// medianOfRuns (bench/repeats.h): one record per case, the median run's.
#include "bench/repeats.h"

#include <gtest/gtest.h>

namespace physdbg::bench {
namespace {

nlohmann::json record(const char* name, int threads, double ours, double peer) {
  nlohmann::json result = {{"name", name},     {"n", 1000},       {"threads", threads},   {"ours_ms", ours},
                           {"peer", "bullet"}, {"peer_ms", peer}, {"ratio", ours / peer}, {"extra", ours * 10}};
  return result;
}

TEST(BenchRepeats, EachCaseTakesTheRunWithTheMedianRatio) {
  const std::vector<std::vector<nlohmann::json>> runs = {
      {record("drop/boxes", 1, 6.0, 10.0), record("drop/boxes", 2, 5.0, 10.0)},
      {record("drop/boxes", 1, 5.0, 10.0), record("drop/boxes", 2, 9.0, 10.0)},
      {record("drop/boxes", 1, 8.0, 10.0), record("drop/boxes", 2, 4.0, 10.0)}};
  const std::vector<nlohmann::json> cases = medianOfRuns(runs);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0]["threads"], 1);
  EXPECT_DOUBLE_EQ(cases[0]["ratio"].get<double>(), 0.6);
  EXPECT_DOUBLE_EQ(cases[0]["ours_ms"].get<double>(), 6.0);  // the whole record of that run
  EXPECT_DOUBLE_EQ(cases[0]["extra"].get<double>(), 60.0);
  EXPECT_EQ(cases[0]["repeats"], 3);
  EXPECT_EQ(cases[0]["ratio_runs"].size(), 3u);
  EXPECT_DOUBLE_EQ(cases[0]["ratio_runs"][2].get<double>(), 0.8);  // run order
  EXPECT_DOUBLE_EQ(cases[0]["ratio_min"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(cases[0]["ratio_max"].get<double>(), 0.8);
  EXPECT_DOUBLE_EQ(cases[1]["ratio"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(cases[1]["ours_ms_runs"][1].get<double>(), 9.0);
}

TEST(BenchRepeats, EvenCountsTakeTheLowerMiddle) {
  const std::vector<std::vector<nlohmann::json>> runs = {{record("pyramid", 1, 4.0, 10.0)},
                                                         {record("pyramid", 1, 7.0, 10.0)},
                                                         {record("pyramid", 1, 5.0, 10.0)},
                                                         {record("pyramid", 1, 9.0, 10.0)}};
  const std::vector<nlohmann::json> cases = medianOfRuns(runs);
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_DOUBLE_EQ(cases[0]["ratio"].get<double>(), 0.5);
}

// The same name, n and threads twice in one run are two cases; a record with
// no peer takes the run with the median own time, and no ratio range.
TEST(BenchRepeats, RepeatedNamesStayApartAndPeerlessCasesUseTheirOwnTime) {
  nlohmann::json alone = {{"name", "render"}, {"n", 991},           {"ours_ms", 30.0},
                          {"peer", nullptr},  {"peer_ms", nullptr}, {"ratio", nullptr}};
  std::vector<std::vector<nlohmann::json>> runs;
  for (double ours : {30.0, 10.0, 20.0}) {
    alone["ours_ms"] = ours;
    runs.push_back({record("tree", 0, 1.0, 2.0), record("tree", 0, ours, 100.0), alone});
  }
  const std::vector<nlohmann::json> cases = medianOfRuns(runs);
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_DOUBLE_EQ(cases[0]["ratio"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(cases[1]["ratio"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(cases[2]["ours_ms"].get<double>(), 20.0);
  EXPECT_TRUE(cases[2]["ratio"].is_null());
  EXPECT_TRUE(cases[2]["ratio_min"].is_null());
}

}  // namespace
}  // namespace physdbg::bench
