// The same-work verdict (side_by_side.h): contact counts within 20% of the
// larger, mean heights within 5% of the body size, nobody outside; null when
// no peer ran. Each limit is tried just inside and just outside.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bench/side_by_side.h"

namespace physdbg::bench {
namespace {

EngineRun run(int contacts, double height, int bodies = 10) {
  EngineRun result;
  result.ran = true;
  result.contacts = contacts;
  result.finalPositions.assign(static_cast<std::size_t>(bodies) + 1, Vec3(0, height, 0));
  result.finalPositions[0] = Vec3(0, -100, 0);  // the floor: not counted
  return result;
}

nlohmann::json verdict(const EngineRun& ours, const EngineRun& peer, double bodySize = 1.0) {
  WorkCheck check;
  check.firstDynamic = 1;
  check.bodySize = bodySize;
  check.outside = [](const Vec3& position) { return position.x() > 5.0; };
  nlohmann::json record;
  addWorkFields(record, ours, peer, check);
  return record;
}

TEST(SameWork, ContactCountsWithinTwentyPercent) {
  EXPECT_TRUE(verdict(run(100, 1.0), run(80, 1.0))["same_work"].get<bool>());
  EXPECT_FALSE(verdict(run(100, 1.0), run(79, 1.0))["same_work"].get<bool>());
  EXPECT_FALSE(verdict(run(79, 1.0), run(100, 1.0))["same_work"].get<bool>());
}

TEST(SameWork, MeanHeightsWithinFivePercentOfTheBodySize) {
  EXPECT_TRUE(verdict(run(100, 1.0), run(100, 1.049))["same_work"].get<bool>());
  EXPECT_FALSE(verdict(run(100, 1.0), run(100, 1.051))["same_work"].get<bool>());
  EXPECT_TRUE(verdict(run(100, 1.0), run(100, 1.09), 2.0)["same_work"].get<bool>());
  const nlohmann::json record = verdict(run(100, 1.0), run(100, 1.2));
  EXPECT_DOUBLE_EQ(record["ours_mean_height"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(record["peer_mean_height"].get<double>(), 1.2);
}

TEST(SameWork, NobodyOutside) {
  EngineRun escaped = run(100, 1.0);
  escaped.finalPositions[3].x() = 6.0;
  const nlohmann::json record = verdict(run(100, 1.0), escaped);
  EXPECT_FALSE(record["same_work"].get<bool>());
  EXPECT_EQ(record["peer_outside"].get<int>(), 1);
  EXPECT_EQ(record["ours_outside"].get<int>(), 0);
  EXPECT_FALSE(verdict(escaped, escaped)["same_work"].get<bool>()) << "both out is no better";
}

TEST(SameWork, IsNullWithoutAPeer) {
  EngineRun none;
  const nlohmann::json record = verdict(run(100, 1.0), none);
  EXPECT_TRUE(record["same_work"].is_null());
  EXPECT_EQ(record["ours_contacts"].get<int>(), 100);
  EXPECT_FALSE(record.contains("peer_contacts"));
}

}  // namespace
}  // namespace physdbg::bench
