#include "engine/broadphase/dynamic_aabb_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include "tests/engine/broadphase/broad_phase_test_helpers.h"

namespace physdbg {
namespace {

using testing::randomBox;
using testing::sortedGrid;
using testing::sortedRow;

DynamicAabbTreeOptions makeOptions(InsertionMethod insertion, bool rotations, double margin = 0.1) {
  DynamicAabbTreeOptions options;
  options.insertion = insertion;
  options.rotations = rotations;
  options.margin = margin;
  return options;
}

// Proxy ids are node indices, not insertion indices: the user data carries the box index.
DynamicAabbTree buildTree(const std::vector<Aabb>& boxes, const DynamicAabbTreeOptions& options,
                          std::vector<int>* proxies = nullptr) {
  DynamicAabbTree tree(options);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const int proxy = tree.createProxy(boxes[i], static_cast<std::uint32_t>(i));
    if (proxies != nullptr) proxies->push_back(proxy);
  }
  return tree;
}

double log2Of(std::size_t n) { return std::log2(static_cast<double>(n)); }

struct OperationsCase {
  InsertionMethod insertion;
  bool rotations;
  unsigned seed;
};

class RandomOperations : public ::testing::TestWithParam<OperationsCase> {};

// Thousands of mixed operations, validating the whole structure after each one.
TEST_P(RandomOperations, TreeStaysValidAfterEveryOperation) {
  const OperationsCase param = GetParam();
  std::mt19937 random(param.seed);
  DynamicAabbTreeOptions options = makeOptions(param.insertion, param.rotations);
  options.velocityPrediction = 2.0;
  DynamicAabbTree tree(options);
  std::map<int, Aabb> tight;  // ordered: picking the k-th live proxy is deterministic
  std::uniform_int_distribution<int> operation(0, 9);
  std::normal_distribution<double> step(0.0, 0.3);
  for (int i = 0; i < 3000; ++i) {
    const int kind = tight.size() < 8 ? 0 : operation(random);
    auto pick = [&] {
      auto it = tight.begin();
      std::advance(it, std::uniform_int_distribution<int>(0, static_cast<int>(tight.size()) - 1)(random));
      return it;
    };
    if (kind <= 3) {
      const Aabb box = randomBox(random, 20.0, 2.0);
      const int proxy = tree.createProxy(box, static_cast<std::uint32_t>(i));
      ASSERT_EQ(tight.count(proxy), 0u) << "id handed out twice";
      tight[proxy] = box;
    } else if (kind <= 5) {
      const auto it = pick();
      tree.destroyProxy(it->first);
      tight.erase(it);
    } else {
      const auto it = pick();
      const Vec3 displacement(step(random), step(random), step(random));
      it->second = Aabb{it->second.min + displacement, it->second.max + displacement};
      tree.moveProxy(it->first, it->second, displacement);
    }
    const std::string problems = tree.validate();
    ASSERT_TRUE(problems.empty()) << "after operation " << i << ": " << problems;
    ASSERT_EQ(tree.proxyCount(), static_cast<int>(tight.size()));
  }
  for (const auto& [proxy, box] : tight) EXPECT_TRUE(tree.fatBox(proxy).contains(box)) << proxy;
}

INSTANTIATE_TEST_SUITE_P(AllInsertionModes, RandomOperations,
                         ::testing::Values(OperationsCase{InsertionMethod::BranchAndBound, true, 1},
                                           OperationsCase{InsertionMethod::BranchAndBound, false, 2},
                                           OperationsCase{InsertionMethod::Greedy, true, 3},
                                           OperationsCase{InsertionMethod::Greedy, false, 4}));

TEST(DynamicAabbTree, ValidateReportsNothingForEmptyAndSingleLeafTrees) {
  DynamicAabbTree tree;
  EXPECT_EQ(tree.validate(), "");
  EXPECT_EQ(tree.height(), 0);
  const int proxy = tree.createProxy(Aabb{Vec3::Zero(), Vec3::Ones()}, 7);
  EXPECT_EQ(tree.validate(), "");
  EXPECT_EQ(tree.nodeCount(), 1);
  EXPECT_EQ(tree.userData(proxy), 7u);
  EXPECT_EQ(tree.surfaceAreaRatio(), 0.0);
  tree.destroyProxy(proxy);
  EXPECT_EQ(tree.nodeCount(), 0);
  EXPECT_EQ(tree.validate(), "");
}

// Sorted input is the worst case of incremental insertion: rotations must keep
// the height logarithmic, and without them the same input must degrade.
TEST(DynamicAabbTree, SortedRowStaysShallowOnlyWithRotations) {
  const std::vector<Aabb> row = sortedRow(1000);
  const DynamicAabbTree rotated = buildTree(row, makeOptions(InsertionMethod::BranchAndBound, true));
  const DynamicAabbTree plain = buildTree(row, makeOptions(InsertionMethod::BranchAndBound, false));
  EXPECT_LT(rotated.height(), 2.0 * log2Of(row.size()));
  EXPECT_GT(plain.height(), 2.0 * log2Of(row.size()));
  EXPECT_GT(plain.height(), 2 * rotated.height());
}

TEST(DynamicAabbTree, SortedGridStaysShallowOnlyWithRotations) {
  const std::vector<Aabb> grid = sortedGrid(32);
  const DynamicAabbTree rotated = buildTree(grid, makeOptions(InsertionMethod::BranchAndBound, true));
  const DynamicAabbTree plain = buildTree(grid, makeOptions(InsertionMethod::BranchAndBound, false));
  EXPECT_LT(rotated.height(), 2.0 * log2Of(grid.size()));
  EXPECT_GT(plain.height(), 2.0 * log2Of(grid.size()));
  EXPECT_GT(plain.height(), 2 * rotated.height());
}

TEST(DynamicAabbTree, GreedyInsertionWithRotationsAlsoStaysShallow) {
  const std::vector<Aabb> row = sortedRow(1000);
  const std::vector<Aabb> grid = sortedGrid(32);
  EXPECT_LT(buildTree(row, makeOptions(InsertionMethod::Greedy, true)).height(), 2.0 * log2Of(row.size()));
  EXPECT_LT(buildTree(grid, makeOptions(InsertionMethod::Greedy, true)).height(), 2.0 * log2Of(grid.size()));
}

// Moving every proxy out of its fat box reinserts it; the tree must stay shallow.
void moveEveryProxy(DynamicAabbTree& tree, const std::vector<Aabb>& boxes, const std::vector<int>& proxies,
                    unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-3.0, 3.0);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Vec3 displacement(offset(random), offset(random), offset(random));
    const Aabb moved{boxes[i].min + displacement, boxes[i].max + displacement};
    EXPECT_TRUE(tree.moveProxy(proxies[i], moved, displacement) || displacement.cwiseAbs().maxCoeff() <= 0.1);
  }
}

TEST(DynamicAabbTree, HeightStaysBoundedAfterMovingEveryProxy) {
  for (const auto& boxes : {sortedRow(1000), sortedGrid(32)}) {
    std::vector<int> rotatedProxies;
    std::vector<int> plainProxies;
    DynamicAabbTree rotated = buildTree(boxes, makeOptions(InsertionMethod::BranchAndBound, true), &rotatedProxies);
    DynamicAabbTree plain = buildTree(boxes, makeOptions(InsertionMethod::BranchAndBound, false), &plainProxies);
    moveEveryProxy(rotated, boxes, rotatedProxies, 5);
    moveEveryProxy(plain, boxes, plainProxies, 5);
    ASSERT_EQ(rotated.validate(), "");
    EXPECT_LT(rotated.height(), 3.0 * log2Of(boxes.size()));
    EXPECT_GT(plain.height(), rotated.height());
  }
}

// Recomputes, for every node, the exact insertion cost (new parent area plus
// ancestors' growth) from a preorder walk, and returns the minimum.
double bruteForceBestCost(const DynamicAabbTree& tree, const Aabb& box) {
  std::vector<double> growthAbove;  // growthAbove[d] = summed growth of the ancestors at depths < d
  std::vector<Aabb> ancestors;
  double best = std::numeric_limits<double>::infinity();
  tree.forEachNode([&](const Aabb& nodeBox, int depth, bool) {
    ancestors.resize(depth);
    growthAbove.resize(depth + 1);
    growthAbove[depth] = depth == 0 ? 0.0
                                    : growthAbove[depth - 1] + ancestors[depth - 1].merged(box).surfaceArea() -
                                          ancestors[depth - 1].surfaceArea();
    best = std::min(best, nodeBox.merged(box).surfaceArea() + growthAbove[depth]);
    ancestors.push_back(nodeBox);
  });
  return best;
}

// Without rotations, the internal area grows by exactly the chosen sibling's
// cost, so branch-and-bound must match the exhaustive minimum and greedy can
// only be worse or equal.
TEST(DynamicAabbTree, BranchAndBoundFindsTheExhaustiveBestSibling) {
  std::mt19937 random(11);
  DynamicAabbTree exact(makeOptions(InsertionMethod::BranchAndBound, false, 0.0));
  DynamicAabbTree greedy(makeOptions(InsertionMethod::Greedy, false, 0.0));
  int greedyWorse = 0;
  for (int i = 0; i < 400; ++i) {
    const Aabb box = randomBox(random, 30.0, 3.0);
    if (i >= 2) {
      const double best = bruteForceBestCost(exact, box);
      const double before = exact.internalArea();
      exact.createProxy(box, 0);
      EXPECT_NEAR(exact.internalArea() - before, best, 1e-9 * exact.internalArea()) << "insertion " << i;
      const double greedyBest = bruteForceBestCost(greedy, box);
      const double greedyBefore = greedy.internalArea();
      greedy.createProxy(box, 0);
      const double greedyCost = greedy.internalArea() - greedyBefore;
      EXPECT_GE(greedyCost, greedyBest - 1e-9 * greedy.internalArea());
      greedyWorse += greedyCost > greedyBest * (1.0 + 1e-9);
    } else {
      exact.createProxy(box, 0);
      greedy.createProxy(box, 0);
    }
  }
  EXPECT_GT(greedyWorse, 0) << "greedy never missed the optimum: the comparison proves nothing";
}

// A move starts the search from the old sibling's cost; the result must still
// be the exhaustive optimum. A copy with the proxy destroyed shows the tree
// the reinsertion searched.
TEST(DynamicAabbTree, ReinsertionAfterAMoveFindsTheExhaustiveBestSibling) {
  std::mt19937 random(12);
  DynamicAabbTree tree(makeOptions(InsertionMethod::BranchAndBound, false, 0.0));
  std::vector<int> proxies;
  std::vector<Aabb> boxes;
  for (int i = 0; i < 300; ++i) {
    boxes.push_back(randomBox(random, 30.0, 3.0));
    proxies.push_back(tree.createProxy(boxes.back(), 0));
  }
  std::normal_distribution<double> step(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    const Vec3 displacement(step(random), step(random), step(random));
    const Aabb moved{boxes[i].min + displacement, boxes[i].max + displacement};
    DynamicAabbTree without = tree;
    without.destroyProxy(proxies[i]);
    const double best = bruteForceBestCost(without, moved);
    ASSERT_TRUE(tree.moveProxy(proxies[i], moved, displacement));
    EXPECT_NEAR(tree.internalArea() - without.internalArea(), best, 1e-9 * tree.internalArea()) << "move " << i;
  }
}

TEST(DynamicAabbTree, TopDownRebuildKeepsProxiesAndImprovesUnrotatedTrees) {
  const std::vector<Aabb> grid = sortedGrid(32);
  std::vector<int> proxies;
  DynamicAabbTree tree = buildTree(grid, makeOptions(InsertionMethod::BranchAndBound, false), &proxies);
  const double sarBefore = tree.surfaceAreaRatio();
  tree.rebuildTopDown();
  ASSERT_EQ(tree.validate(), "");
  EXPECT_EQ(tree.proxyCount(), static_cast<int>(grid.size()));
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_TRUE(tree.fatBox(proxies[i]).contains(grid[i]));
    EXPECT_EQ(tree.userData(proxies[i]), i);
  }
  EXPECT_LT(tree.surfaceAreaRatio(), sarBefore);
  EXPECT_LT(tree.height(), 2.0 * log2Of(grid.size()));
  // The rebuilt tree stays a working dynamic tree.
  tree.destroyProxy(proxies[5]);
  tree.createProxy(grid[5], 5);
  EXPECT_EQ(tree.validate(), "");
}

// Rotations on sorted input should bring incremental quality close to the top-down build.
TEST(DynamicAabbTree, RotatedSortedInsertionApproachesTopDownQuality) {
  for (const auto& boxes : {sortedRow(1000), sortedGrid(32)}) {
    DynamicAabbTree tree = buildTree(boxes, makeOptions(InsertionMethod::BranchAndBound, true));
    const double incremental = tree.surfaceAreaRatio();
    tree.rebuildTopDown();
    EXPECT_LT(incremental, 1.25 * tree.surfaceAreaRatio());
  }
}

// The "tiles" scene: 200 x 10 tiles row by row, then a 20-row
// pyramid on top, inserted one by one. Goal: within 1.10x of the top-down
// SAH build's surface area ratio (measured 1.097; 1.19 with child-grandchild
// rotations only).
TEST(DynamicAabbTree, SortedTilesWithRotationsComeWithinTenPercentOfTopDown) {
  std::vector<Aabb> tiles;
  for (int row = 0; row < 10; ++row)
    for (int column = 0; column < 200; ++column)
      tiles.push_back(Aabb::fromCenterHalfExtents(Vec3(column - 100.0, -row, 0.0), Vec3::Constant(0.5)));
  for (int level = 0; level < 20; ++level)
    for (int i = 0; i < 20 - level; ++i)
      tiles.push_back(Aabb::fromCenterHalfExtents(Vec3(i - 0.5 * (19 - level), 1.0 + level, 0.0), Vec3::Constant(0.5)));
  DynamicAabbTree tree = buildTree(tiles, makeOptions(InsertionMethod::BranchAndBound, true, 0.0));
  EXPECT_EQ(tree.validate(), "");
  const double incremental = tree.surfaceAreaRatio();
  tree.rebuildTopDown();
  EXPECT_LT(incremental, 1.10 * tree.surfaceAreaRatio());
}

// A 3D lattice in sorted order is full of exact cost ties; resolving them to
// the deeper candidate ended at 1.87x the top-down SAR and height 35 at 24^3.
TEST(DynamicAabbTree, SortedLatticeInsertionDoesNotDegrade) {
  std::vector<Aabb> lattice;
  for (int z = 0; z < 24; ++z) {
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 24; ++x)
        lattice.push_back(Aabb::fromCenterHalfExtents(2.0 * Vec3(x, y, z), Vec3::Constant(0.5)));
    }
  }
  DynamicAabbTree tree = buildTree(lattice, makeOptions(InsertionMethod::BranchAndBound, true, 0.0));
  const double incremental = tree.surfaceAreaRatio();
  EXPECT_LT(tree.height(), 2.0 * log2Of(lattice.size()));
  tree.rebuildTopDown();
  EXPECT_LT(incremental, 1.5 * tree.surfaceAreaRatio());
}

TEST(DynamicAabbTree, RotationLogIsOffByDefaultAndRecordsImprovements) {
  const std::vector<Aabb> row = sortedRow(64);
  DynamicAabbTree silent = buildTree(row, makeOptions(InsertionMethod::BranchAndBound, true));
  EXPECT_TRUE(silent.rotationLog().empty());

  DynamicAabbTree logged(makeOptions(InsertionMethod::BranchAndBound, true));
  logged.setRotationLogEnabled(true);
  for (std::size_t i = 0; i < row.size(); ++i) logged.createProxy(row[i], 0);
  ASSERT_FALSE(logged.rotationLog().empty());
  for (const RotationEvent& event : logged.rotationLog()) {
    EXPECT_LT(event.areaAfter, event.areaBefore);
    EXPECT_LT(event.sarAfter, event.sarBefore);
    EXPECT_NE(event.first, event.second);
  }
  EXPECT_EQ(logged.height(), silent.height()) << "logging must not change the tree";
  logged.clearRotationLog();
  EXPECT_TRUE(logged.rotationLog().empty());
}

TEST(DynamicAabbTree, MoveInsideFatBoxDoesNothingAndPredictionStretchesForward) {
  DynamicAabbTreeOptions options;
  options.margin = 0.5;
  options.velocityPrediction = 4.0;
  DynamicAabbTree tree(options);
  const Aabb box{Vec3::Zero(), Vec3::Ones()};
  const int proxy = tree.createProxy(box, 0);
  tree.createProxy(Aabb{Vec3(5, 5, 5), Vec3(6, 6, 6)}, 1);
  const Aabb fat = tree.fatBox(proxy);
  const Vec3 small(0.4, 0, 0);
  EXPECT_FALSE(tree.moveProxy(proxy, Aabb{box.min + small, box.max + small}, small));
  EXPECT_TRUE(tree.fatBox(proxy).min.isApprox(fat.min) && tree.fatBox(proxy).max.isApprox(fat.max));
  const Vec3 large(1.0, 0, -0.25);
  const Aabb moved{box.min + large, box.max + large};
  EXPECT_TRUE(tree.moveProxy(proxy, moved, large));
  const Aabb& stretched = tree.fatBox(proxy);
  // margin 0.5 on every side, plus 4 x displacement towards the motion only.
  EXPECT_NEAR(stretched.max.x(), moved.max.x() + 0.5 + 4.0, 1e-12);
  EXPECT_NEAR(stretched.min.x(), moved.min.x() - 0.5, 1e-12);
  EXPECT_NEAR(stretched.min.z(), moved.min.z() - 0.5 - 1.0, 1e-12);
  EXPECT_NEAR(stretched.max.z(), moved.max.z() + 0.5, 1e-12);
  EXPECT_EQ(tree.validate(), "");
}

std::vector<int> sorted(std::vector<int> values) {
  std::sort(values.begin(), values.end());
  return values;
}

TEST(DynamicAabbTree, QueryEqualsBruteForce) {
  std::mt19937 random(21);
  DynamicAabbTree tree;
  std::vector<int> proxies;
  for (int i = 0; i < 500; ++i) proxies.push_back(tree.createProxy(randomBox(random, 20.0, 1.5), 0));
  for (int q = 0; q < 200; ++q) {
    const Aabb box = randomBox(random, 22.0, 4.0);
    std::vector<int> found;
    tree.query(box, [&](int proxy) {
      found.push_back(proxy);
      return true;
    });
    std::vector<int> expected;
    for (const int proxy : proxies) {
      if (tree.fatBox(proxy).overlaps(box)) expected.push_back(proxy);
    }
    EXPECT_EQ(sorted(found), expected);
  }
  int visits = 0;
  tree.query(tree.fatBox(proxies[0]), [&](int) { return ++visits < 1; });
  EXPECT_EQ(visits, 1) << "returning false must stop the query";
}

struct Ray {
  Vec3 origin, direction;
};

TEST(DynamicAabbTree, RayCastEqualsBruteForce) {
  std::mt19937 random(31);
  DynamicAabbTree tree;
  std::vector<int> proxies;
  for (int i = 0; i < 400; ++i) proxies.push_back(tree.createProxy(randomBox(random, 20.0, 1.5), 0));
  std::uniform_real_distribution<double> coordinate(-25.0, 25.0);
  std::vector<Ray> rays;
  for (int r = 0; r < 200; ++r) {
    const Vec3 from(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 to(coordinate(random), coordinate(random), coordinate(random));
    rays.push_back({from, to - from});
  }
  rays.push_back({Vec3(-30, 0, 0), Vec3(60, 0, 0)});  // axis-parallel: infinite inverse components
  rays.push_back({Vec3(0, -30, 0.5), Vec3(0, 60, 0)});
  for (const Ray& ray : rays) {
    const Vec3 inverse = ray.direction.cwiseInverse();
    std::vector<int> expectedHits;
    double expectedClosest = 2.0;
    for (const int proxy : proxies) {
      const double t = segmentEntry(tree.fatBox(proxy), ray.origin, inverse, 1.0);
      if (t < 0.0) continue;
      expectedHits.push_back(proxy);
      expectedClosest = std::min(expectedClosest, t);
    }
    std::vector<int> hits;  // ignore every hit: all of them must be reported
    tree.rayCast(ray.origin, ray.direction, 1.0, [&](int proxy, double) {
      hits.push_back(proxy);
      return -1.0;
    });
    EXPECT_EQ(sorted(hits), expectedHits);
    double closest = 2.0;
    int callbacks = 0;
    tree.rayCast(ray.origin, ray.direction, 1.0, [&](int proxy, double maxFraction) {
      ++callbacks;
      const double t = segmentEntry(tree.fatBox(proxy), ray.origin, inverse, maxFraction);
      EXPECT_GE(t, 0.0) << "reported a proxy beyond the clipped segment";
      closest = std::min(closest, t);
      return t;
    });
    EXPECT_EQ(closest, expectedClosest);
    EXPECT_LE(callbacks, static_cast<int>(expectedHits.size()));
  }
}

TEST(DynamicAabbTree, ForEachNodeVisitsEveryNodeWithItsDepth) {
  std::mt19937 random(41);
  DynamicAabbTree tree;
  for (int i = 0; i < 300; ++i) tree.createProxy(randomBox(random, 10.0, 1.0), 0);
  int nodes = 0;
  int leaves = 0;
  int deepest = 0;
  tree.forEachNode([&](const Aabb&, int depth, bool isLeaf) {
    ++nodes;
    leaves += isLeaf;
    deepest = std::max(deepest, depth);
  });
  EXPECT_EQ(nodes, tree.nodeCount());
  EXPECT_EQ(leaves, 300);
  EXPECT_EQ(deepest, tree.height());
}

TEST(DynamicAabbTree, BadInputThrows) {
  DynamicAabbTree tree;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(tree.createProxy(Aabb{Vec3(nan, 0, 0), Vec3::Ones()}, 0), std::invalid_argument);
  EXPECT_THROW(tree.createProxy(Aabb{Vec3::Ones(), Vec3::Zero()}, 0), std::invalid_argument);
  const int proxy = tree.createProxy(Aabb{Vec3::Zero(), Vec3::Ones()}, 0);
  const int other = tree.createProxy(Aabb{Vec3::Ones(), Vec3::Constant(2)}, 0);
  EXPECT_THROW(tree.moveProxy(proxy, Aabb{Vec3::Zero(), Vec3(1, nan, 1)}), std::invalid_argument);
  EXPECT_THROW(tree.moveProxy(proxy, Aabb{Vec3::Zero(), Vec3::Ones()}, Vec3(nan, 0, 0)), std::invalid_argument);
  EXPECT_THROW(tree.destroyProxy(-1), std::invalid_argument);
  EXPECT_THROW(tree.destroyProxy(99), std::invalid_argument);
  const int parent = tree.root();  // an internal node is not a proxy
  EXPECT_NE(parent, proxy);
  EXPECT_THROW(tree.destroyProxy(parent), std::invalid_argument);
  tree.destroyProxy(other);
  EXPECT_THROW(tree.destroyProxy(other), std::invalid_argument);
  EXPECT_THROW(tree.fatBox(other), std::invalid_argument);
  DynamicAabbTreeOptions negative;
  negative.margin = -1.0;
  EXPECT_THROW(DynamicAabbTree{negative}, std::invalid_argument);
  EXPECT_EQ(tree.validate(), "");
}

}  // namespace
}  // namespace physdbg
