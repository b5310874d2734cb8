#include "engine/broadphase/tree_broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/baselines/brute_force_broad_phase.h"
#include "engine/parallel/task_system.h"
#include "tests/engine/broadphase/broad_phase_test_helpers.h"

namespace physdbg {
namespace {

using testing::latticeBox;
using testing::randomBox;

struct ProxyRecord {
  Aabb box;
  std::uint32_t body;
  ProxyMotion motion;
  bool active = true;
};

// The contract, computed directly from the broad phase's own fat boxes.
std::vector<BodyPair> expectedPairs(const BroadPhase& broadPhase, const std::map<int, ProxyRecord>& proxies) {
  std::vector<BodyPair> pairs;
  auto drives = [](const ProxyRecord& r) { return r.motion == ProxyMotion::Dynamic && r.active; };
  for (auto first = proxies.begin(); first != proxies.end(); ++first) {
    for (auto second = std::next(first); second != proxies.end(); ++second) {
      const ProxyRecord& a = first->second;
      const ProxyRecord& b = second->second;
      if (a.body == b.body || (!drives(a) && !drives(b))) continue;
      if (!broadPhase.fatBox(first->first).overlaps(broadPhase.fatBox(second->first))) continue;
      pairs.push_back({std::min(a.body, b.body), std::max(a.body, b.body)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

void expectStrictlySorted(const std::vector<BodyPair>& pairs) {
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_LT(pairs[i].a, pairs[i].b);
    if (i > 0) {
      EXPECT_LT(pairs[i - 1], pairs[i]) << "duplicate or unsorted pair at " << i;
    }
  }
}

// Random scenes with every kind of change between findPairs calls: moves that
// stay inside or leave fat boxes, sleep and wake, adds and removes. Lattice
// boxes touch exactly and some proxies are added twice with the same box.
void runRandomScene(BroadPhase& broadPhase, unsigned seed, bool lattice) {
  std::mt19937 random(seed);
  std::map<int, ProxyRecord> proxies;
  std::uint32_t nextBody = 0;
  auto makeBox = [&] { return lattice ? latticeBox(random, 8) : randomBox(random, 12.0, 1.5); };
  auto add = [&](const Aabb& box) {
    const ProxyMotion motion = random() % 3 == 0 ? ProxyMotion::Static : ProxyMotion::Dynamic;
    const std::uint32_t body = nextBody++;
    proxies[broadPhase.addProxy(box, body, motion)] = {box, body, motion};
  };
  for (int i = 0; i < 150; ++i) {
    const Aabb box = makeBox();
    add(box);
    if (i % 10 == 0) add(box);  // identical boxes
  }
  std::normal_distribution<double> step(0.0, 0.15);
  std::vector<BodyPair> pairs;
  for (int frame = 0; frame < 40; ++frame) {
    for (auto& [proxy, record] : proxies) {
      const unsigned roll = random() % 10;
      if (roll < 5 && record.motion == ProxyMotion::Dynamic && record.active) {
        const Vec3 displacement(step(random), step(random), step(random));
        record.box = {record.box.min + displacement, record.box.max + displacement};
        broadPhase.moveProxy(proxy, record.box, displacement);
      } else if (roll == 5 && record.motion == ProxyMotion::Dynamic) {
        record.active = !record.active;
        broadPhase.setProxyActive(proxy, record.active);
      }
    }
    for (int change = 0; change < 5; ++change) {
      auto it = proxies.begin();
      std::advance(it, random() % proxies.size());
      broadPhase.removeProxy(it->first);
      proxies.erase(it);
      add(makeBox());
    }
    broadPhase.findPairs(pairs);
    ASSERT_EQ(pairs, expectedPairs(broadPhase, proxies)) << "frame " << frame;
    expectStrictlySorted(pairs);
  }
  EXPECT_FALSE(pairs.empty()) << "scene too sparse to test anything";
}

TEST(TreeBroadPhase, PairsEqualBruteForceOnRandomScenes) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    TreeBroadPhase broadPhase;
    runRandomScene(broadPhase, seed, false);
    EXPECT_EQ(broadPhase.tree().validate(), "");
  }
}

TEST(TreeBroadPhase, PairsEqualBruteForceWithTouchingAndIdenticalBoxes) {
  for (const double margin : {0.0, 0.2}) {
    DynamicAabbTreeOptions options;
    options.margin = margin;
    options.velocityPrediction = 1.0;
    TreeBroadPhase broadPhase(options);
    runRandomScene(broadPhase, 7, true);
  }
}

// The pair query's stack is sized from the tree's height: a tree built from
// a sorted row without rotations is a long chain, far deeper than any stack
// a balanced tree needs, and must still give every pair.
TEST(TreeBroadPhase, PairsEqualBruteForceOnADegenerateDeepTree) {
  DynamicAabbTreeOptions options;
  options.rotations = false;
  TreeBroadPhase broadPhase(options);
  std::map<int, ProxyRecord> proxies;
  const std::vector<Aabb> row = testing::sortedRow(400);
  for (std::size_t i = 0; i < row.size(); ++i) {
    const auto body = static_cast<std::uint32_t>(i);
    proxies[broadPhase.addProxy(row[i], body, ProxyMotion::Dynamic)] = {row[i], body, ProxyMotion::Dynamic};
  }
  EXPECT_GT(broadPhase.tree().height(), 100);
  std::mt19937 random(11);
  std::normal_distribution<double> step(0.0, 0.3);
  std::vector<BodyPair> pairs;
  for (int frame = 0; frame < 5; ++frame) {
    for (auto& [proxy, record] : proxies) {
      const Vec3 displacement(step(random), step(random), step(random));
      record.box = {record.box.min + displacement, record.box.max + displacement};
      broadPhase.moveProxy(proxy, record.box, displacement);
    }
    broadPhase.findPairs(pairs);
    ASSERT_EQ(pairs, expectedPairs(broadPhase, proxies)) << "frame " << frame;
  }
  EXPECT_FALSE(pairs.empty());
}

// Enough changed proxies that the queries run in parallel pieces
// (parallelQueryMinimum): 1, 2 and 4 threads must give the same pairs and
// the same counters every frame, and the pairs the contract asks for. Each
// frame also removes and re-adds proxies, and some bodies have two.
TEST(TreeBroadPhase, ThreadsGiveTheSamePairsAndCounters) {
  TaskSystem two(2), four(4);
  std::vector<TreeBroadPhase> broadPhases;
  broadPhases.reserve(3);
  broadPhases.emplace_back();
  broadPhases.emplace_back(DynamicAabbTreeOptions{}, &two);
  broadPhases.emplace_back(DynamicAabbTreeOptions{}, &four);
  const int count = TreeBroadPhase::parallelQueryMinimum + 2000;
  std::mt19937 random(23);
  std::map<int, ProxyRecord> proxies;
  const auto add = [&](std::uint32_t body, ProxyMotion motion) {
    const Aabb box = randomBox(random, 30.0, 0.8);
    int proxy = -1;
    for (TreeBroadPhase& broadPhase : broadPhases) {
      const int id = broadPhase.addProxy(box, body, motion);
      ASSERT_TRUE(proxy == -1 || proxy == id);
      proxy = id;
    }
    proxies[proxy] = {box, body, motion};
  };
  for (int body = 0; body < count; ++body) {
    const ProxyMotion motion = body % 7 == 0 ? ProxyMotion::Static : ProxyMotion::Dynamic;
    add(static_cast<std::uint32_t>(body), motion);
    if (body % 50 == 0) add(static_cast<std::uint32_t>(body), motion);  // a second proxy of the same body
  }
  std::normal_distribution<double> step(0.0, 0.3);
  for (int frame = 0; frame < 4; ++frame) {
    if (frame > 0) {
      for (auto& [proxy, record] : proxies) {
        if (record.motion == ProxyMotion::Static) continue;
        if (random() % 50 == 0) {
          record.active = !record.active;
          for (TreeBroadPhase& broadPhase : broadPhases) broadPhase.setProxyActive(proxy, record.active);
        }
        const Vec3 displacement(step(random), step(random), step(random));
        record.box = {record.box.min + displacement, record.box.max + displacement};
        for (TreeBroadPhase& broadPhase : broadPhases) broadPhase.moveProxy(proxy, record.box, displacement);
      }
      for (int change = 0; change < 20; ++change) {
        auto it = proxies.begin();
        std::advance(it, random() % proxies.size());
        const auto [body, motion] = std::pair{it->second.body, it->second.motion};
        for (TreeBroadPhase& broadPhase : broadPhases) broadPhase.removeProxy(it->first);
        proxies.erase(it);
        add(body, motion);
      }
    }
    std::vector<BodyPair> serial, parallel;
    broadPhases[0].findPairs(serial);
    ASSERT_GE(broadPhases[0].stats().proxiesReinserted, frame == 0 ? 0 : TreeBroadPhase::parallelQueryMinimum)
        << "too few queries to split";
    for (std::size_t i = 1; i < broadPhases.size(); ++i) {
      broadPhases[i].findPairs(parallel);
      ASSERT_EQ(parallel, serial) << "frame " << frame << ", broad phase " << i;
      EXPECT_EQ(broadPhases[i].stats().nodesVisited, broadPhases[0].stats().nodesVisited);
      EXPECT_EQ(broadPhases[i].stats().proxiesReinserted, broadPhases[0].stats().proxiesReinserted);
    }
    if (frame == 0 || frame == 3) {
      ASSERT_EQ(serial, expectedPairs(broadPhases[0], proxies)) << "frame " << frame;
    }
  }
}

TEST(BruteForceBroadPhase, PairsFollowTheContractInBothLoopModes) {
  for (const bool bothOrders : {false, true}) {
    BruteForceOptions options;
    options.checkBothOrders = bothOrders;
    BruteForceBroadPhase broadPhase(options);
    runRandomScene(broadPhase, 9, true);
  }
}

TEST(BruteForceBroadPhase, CheckingBothOrdersDoublesTheTestsNotThePairs) {
  BruteForceOptions once;
  BruteForceOptions twice;
  twice.checkBothOrders = true;
  BruteForceBroadPhase single(once);
  BruteForceBroadPhase doubled(twice);
  for (int i = 0; i < 10; ++i) {
    const Aabb box = Aabb::fromCenterHalfExtents(Vec3(0.9 * i, 0, 0), Vec3::Constant(0.5));
    single.addProxy(box, i, ProxyMotion::Dynamic);
    doubled.addProxy(box, i, ProxyMotion::Dynamic);
  }
  std::vector<BodyPair> first;
  std::vector<BodyPair> second;
  single.findPairs(first);
  doubled.findPairs(second);
  EXPECT_EQ(first, second);
  EXPECT_EQ(first.size(), 9u);  // spacing 0.9 < 1: only neighbours overlap
  EXPECT_EQ(single.stats().boxesTested, 45);
  EXPECT_EQ(doubled.stats().boxesTested, 90);
}

// Static-static and sleeping pairs never appear; waking brings them back.
TEST(TreeBroadPhase, OnlyActiveDynamicProxiesMakePairs) {
  TreeBroadPhase broadPhase;
  const Aabb box{Vec3::Zero(), Vec3::Ones()};
  broadPhase.addProxy(box, 0, ProxyMotion::Static);
  broadPhase.addProxy(box, 1, ProxyMotion::Static);
  const int sleeper = broadPhase.addProxy(box, 2, ProxyMotion::Dynamic);
  const int other = broadPhase.addProxy(box, 3, ProxyMotion::Dynamic);
  std::vector<BodyPair> pairs;
  broadPhase.findPairs(pairs);
  EXPECT_EQ(pairs.size(), 5u);  // every pair but 0-1
  broadPhase.setProxyActive(sleeper, false);
  broadPhase.setProxyActive(other, false);
  broadPhase.findPairs(pairs);
  EXPECT_TRUE(pairs.empty());
  broadPhase.setProxyActive(other, true);
  broadPhase.findPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{0, 3}, {1, 3}, {2, 3}}));
}

// "No check between objects that have not moved": a step with no reinsertion
// visits no node, yet returns the same pairs as before.
TEST(TreeBroadPhase, UnchangedProxiesAreNotQueriedAgain) {
  TreeBroadPhase broadPhase;
  std::vector<int> proxies;
  for (int i = 0; i < 50; ++i) {
    proxies.push_back(broadPhase.addProxy(Aabb::fromCenterHalfExtents(Vec3(0.9 * i, 0, 0), Vec3::Constant(0.5)), i,
                                          ProxyMotion::Dynamic));
  }
  std::vector<BodyPair> first;
  broadPhase.findPairs(first);
  EXPECT_GT(broadPhase.stats().nodesVisited, 0);
  const Vec3 nudge(0.05, 0, 0);  // within the 0.1 margin
  for (int i = 0; i < 50; ++i) {
    broadPhase.moveProxy(proxies[i], Aabb::fromCenterHalfExtents(Vec3(0.9 * i, 0, 0) + nudge, Vec3::Constant(0.5)),
                         nudge);
  }
  std::vector<BodyPair> second;
  broadPhase.findPairs(second);
  EXPECT_EQ(broadPhase.stats().nodesVisited, 0);
  EXPECT_EQ(broadPhase.stats().proxiesReinserted, 0);
  EXPECT_EQ(first, second);
  const Vec3 jump(0, 5, 0);
  broadPhase.moveProxy(proxies[10], Aabb::fromCenterHalfExtents(Vec3(9, 0, 0) + jump, Vec3::Constant(0.5)), jump);
  broadPhase.findPairs(second);
  EXPECT_EQ(broadPhase.stats().proxiesReinserted, 1);
  EXPECT_EQ(second.size(), first.size() - 2);
}

TEST(TreeBroadPhase, ProxiesOfOneBodyMakeOnePairAndNoSelfPair) {
  TreeBroadPhase broadPhase;
  const Aabb box{Vec3::Zero(), Vec3::Ones()};
  broadPhase.addProxy(box, 4, ProxyMotion::Dynamic);
  broadPhase.addProxy(box, 4, ProxyMotion::Dynamic);
  broadPhase.addProxy(box, 2, ProxyMotion::Dynamic);
  std::vector<BodyPair> pairs;
  broadPhase.findPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{2, 4}}));
}

TEST(TreeBroadPhase, RemovedProxiesLoseTheirPairsAndIdsAreReused) {
  TreeBroadPhase broadPhase;
  const Aabb box{Vec3::Zero(), Vec3::Ones()};
  broadPhase.addProxy(box, 0, ProxyMotion::Dynamic);
  const int removed = broadPhase.addProxy(box, 1, ProxyMotion::Dynamic);
  std::vector<BodyPair> pairs;
  broadPhase.findPairs(pairs);
  ASSERT_EQ(pairs.size(), 1u);
  broadPhase.removeProxy(removed);
  const int far = broadPhase.addProxy(Aabb{Vec3::Constant(10), Vec3::Constant(11)}, 2, ProxyMotion::Dynamic);
  broadPhase.findPairs(pairs);
  EXPECT_TRUE(pairs.empty());
  EXPECT_EQ(broadPhase.tree().isProxy(removed), removed == far);
}

TEST(BroadPhases, BadInputThrows) {
  TreeBroadPhase tree;
  BruteForceBroadPhase brute;
  for (BroadPhase* broadPhase : std::initializer_list<BroadPhase*>{&tree, &brute}) {
    EXPECT_THROW(broadPhase->addProxy(Aabb{Vec3::Ones(), Vec3::Zero()}, 0, ProxyMotion::Dynamic),
                 std::invalid_argument);
    const int proxy = broadPhase->addProxy(Aabb{Vec3::Zero(), Vec3::Ones()}, 0, ProxyMotion::Dynamic);
    EXPECT_THROW(broadPhase->moveProxy(proxy + 100, Aabb{}, Vec3::Zero()), std::invalid_argument);
    EXPECT_THROW(broadPhase->setProxyActive(-3, true), std::invalid_argument);
    EXPECT_THROW(broadPhase->moveProxy(proxy, Aabb{Vec3::Ones(), Vec3::Zero()}, Vec3::Zero()),
                 std::invalid_argument);
    broadPhase->removeProxy(proxy);
    EXPECT_THROW(broadPhase->removeProxy(proxy), std::invalid_argument);
    EXPECT_THROW(broadPhase->fatBox(proxy), std::invalid_argument);
  }
  BruteForceOptions negative;
  negative.margin = -0.5;
  EXPECT_THROW(BruteForceBroadPhase{negative}, std::invalid_argument);
}

}  // namespace
}  // namespace physdbg
