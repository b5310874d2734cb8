// WarmStartMemory carries the last step's impulses into this step's
// manifolds: by pair and feature id, else to the nearest unused old point
// within reach in A's frame, each old point at most once; the same for any
// split of the manifolds over threads.
#include "engine/solver/warm_start_memory.h"

#include <gtest/gtest.h>

#include <random>

#include "engine/parallel/task_system.h"

namespace physdbg {
namespace {

ContactManifold manifold(std::uint32_t a, std::uint32_t b, int points) {
  ContactManifold result;
  result.a = a;
  result.b = b;
  result.pointCount = points;
  for (int p = 0; p < points; ++p) {
    result.points[p].featureId = static_cast<std::uint32_t>(10 + p);
    result.points[p].localA = Vec3(p, 0, 0);
    result.points[p].normalImpulse = 1.0 + p;
    result.points[p].tangentImpulse[0] = 0.1 * p;
    result.points[p].tangentImpulse[1] = -0.2 * p;
  }
  return result;
}

TEST(WarmStartMemory, SamePairAndFeatureCarriesTheImpulses) {
  WarmStartMemory memory;
  memory.remember({manifold(0, 1, 4), manifold(1, 2, 1)});
  std::vector<ContactManifold> now = {manifold(0, 1, 4), manifold(1, 2, 1), manifold(2, 3, 1)};
  for (ContactManifold& m : now)
    for (ManifoldPoint& point : m.points) point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
  std::swap(now[0].points[0].featureId, now[0].points[3].featureId);  // matched by id, not by slot
  memory.carryInto(now, 0.005, nullptr);
  EXPECT_EQ(now[0].points[0].normalImpulse, 4.0);
  EXPECT_EQ(now[0].points[3].normalImpulse, 1.0);
  EXPECT_EQ(now[0].points[2].tangentImpulse[1], -0.4);
  EXPECT_EQ(now[1].points[0].normalImpulse, 1.0);
  EXPECT_EQ(now[2].points[0].normalImpulse, 0.0);  // a new pair starts cold
}

TEST(WarmStartMemory, ANewFeatureTakesTheNearestUnusedOldPointWithinReach) {
  WarmStartMemory memory;
  memory.remember({manifold(0, 1, 2)});
  std::vector<ContactManifold> now = {manifold(0, 1, 2)};
  now[0].points[0].featureId = 99;
  now[0].points[0].localA = Vec3(0.004, 0, 0);  // within 5 mm of old point 0
  now[0].points[1].featureId = 98;
  now[0].points[1].localA = Vec3(0.003, 0, 0);  // nearer to old point 0 too, which is taken
  for (ManifoldPoint& point : now[0].points) point.normalImpulse = 0.0;
  memory.carryInto(now, 0.005, nullptr);
  EXPECT_EQ(now[0].points[0].normalImpulse, 1.0);
  EXPECT_EQ(now[0].points[1].normalImpulse, 0.0);  // old point 1 is 1 m away
}

TEST(WarmStartMemory, EverySplitOverThreadsCarriesTheSame) {
  std::mt19937 random(7);
  std::vector<ContactManifold> before, now;
  for (std::uint32_t a = 0; a < 3000; ++a) {
    before.push_back(manifold(a, a + 1, 1 + static_cast<int>(random() % 4)));
    if (random() % 3 != 0) now.push_back(before.back());  // a pair that persists, its points too
  }
  WarmStartMemory memory;
  memory.remember(before);
  EXPECT_EQ(memory.size(), before.size());
  std::vector<ContactManifold> alone = now, split = now;
  for (auto* list : {&alone, &split})
    for (ContactManifold& m : *list)
      for (ManifoldPoint& point : m.points) point.normalImpulse = 0.0;
  memory.carryInto(alone, 0.005, nullptr);
  const TaskSystem tasks(4);
  memory.carryInto(split, 0.005, &tasks);
  for (std::size_t m = 0; m < now.size(); ++m)
    for (int p = 0; p < now[m].pointCount; ++p) {
      EXPECT_EQ(alone[m].points[p].normalImpulse, split[m].points[p].normalImpulse);
      EXPECT_EQ(alone[m].points[p].normalImpulse, now[m].points[p].normalImpulse);  // every point found again
    }
}

}  // namespace
}  // namespace physdbg
