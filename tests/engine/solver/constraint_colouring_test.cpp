// Graph colouring of contact manifolds (engine/solver/constraint_colouring.h):
// on random graphs with fixed seeds, every manifold is in exactly one colour
// or the overflow, no movable body appears twice in a colour (immovable ones
// may), and the same input gives the same colouring.
#include "engine/solver/constraint_colouring.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace physdbg {
namespace {

struct Graph {
  std::vector<ContactManifold> manifolds;
  std::vector<bool> movable;
  std::vector<std::uint32_t> island;  // every manifold, ascending
};

// `bodies` bodies, each immovable with probability `immovableShare`, joined
// by `count` manifolds between random distinct pairs (a < b), in pair order.
Graph randomGraph(unsigned seed, std::uint32_t bodies, std::size_t count, double immovableShare) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::uint32_t> body(0, bodies - 1);
  std::bernoulli_distribution immovable(immovableShare);
  Graph graph;
  for (std::uint32_t i = 0; i < bodies; ++i) graph.movable.push_back(!immovable(random));
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  while (pairs.size() < count) {
    std::uint32_t a = body(random), b = body(random);
    if (a == b || (!graph.movable[a] && !graph.movable[b])) continue;
    pairs.insert({std::min(a, b), std::max(a, b)});
  }
  for (const auto& [a, b] : pairs) {
    ContactManifold& manifold = graph.manifolds.emplace_back();
    manifold.a = a;
    manifold.b = b;
  }
  graph.island.resize(graph.manifolds.size());
  std::iota(graph.island.begin(), graph.island.end(), 0u);
  return graph;
}

// Body 0 touching bodies 1..count; body 0 movable or not.
Graph starGraph(std::uint32_t count, bool hubMovable) {
  Graph graph;
  graph.movable.assign(count + 1, true);
  graph.movable[0] = hubMovable;
  for (std::uint32_t i = 1; i <= count; ++i) {
    ContactManifold& manifold = graph.manifolds.emplace_back();
    manifold.a = 0;
    manifold.b = i;
    graph.island.push_back(i - 1);
  }
  return graph;
}

void expectValid(const Graph& graph, const ConstraintColouring& colouring) {
  std::vector<int> seen(graph.manifolds.size(), 0);
  EXPECT_LE(colouring.colours.size(), static_cast<std::size_t>(ConstraintColouring::maxColours));
  for (const std::vector<std::uint32_t>& colour : colouring.colours) {
    EXPECT_FALSE(colour.empty());
    EXPECT_TRUE(std::is_sorted(colour.begin(), colour.end()));
    std::set<std::uint32_t> used;
    for (std::uint32_t m : colour) {
      ++seen.at(m);
      for (std::uint32_t id : {graph.manifolds[m].a, graph.manifolds[m].b})
        if (graph.movable[id]) {
          EXPECT_TRUE(used.insert(id).second) << "body " << id << " twice in a colour";
        }
    }
  }
  for (std::uint32_t m : colouring.overflow) ++seen.at(m);
  for (std::size_t m = 0; m < seen.size(); ++m) EXPECT_EQ(seen[m], 1) << "manifold " << m;
}

TEST(ConstraintColouring, RandomGraphsAreValid) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Graph graph = randomGraph(seed, 40 + 10 * seed, 3 * (40 + 10 * seed), seed % 4 * 0.1);
    const ConstraintColouring colouring = colourConstraints(graph.manifolds, graph.island, graph.movable);
    SCOPED_TRACE(seed);
    expectValid(graph, colouring);
  }
}

TEST(ConstraintColouring, DenseGraphsOverflowAndStayValid) {
  const Graph graph = randomGraph(7, 30, 300, 0.0);  // about 20 contacts a body
  const ConstraintColouring colouring = colourConstraints(graph.manifolds, graph.island, graph.movable, 8);
  expectValid(graph, colouring);
  EXPECT_EQ(colouring.colours.size(), 8u);
  EXPECT_FALSE(colouring.overflow.empty());
}

TEST(ConstraintColouring, ImmovableBodiesAreShared) {
  // Fifty boxes on one floor (body 0) and nothing else: one colour.
  const Graph graph = starGraph(50, false);
  const ConstraintColouring colouring = colourConstraints(graph.manifolds, graph.island, graph.movable);
  ASSERT_EQ(colouring.colours.size(), 1u);
  EXPECT_EQ(colouring.colours[0].size(), 50u);
  EXPECT_TRUE(colouring.overflow.empty());
}

TEST(ConstraintColouring, ABodyWithMoreContactsThanColoursOverflows) {
  // A movable hub touching 30 others needs 30 colours; 24 exist.
  const Graph graph = starGraph(30, true);
  const ConstraintColouring colouring = colourConstraints(graph.manifolds, graph.island, graph.movable);
  expectValid(graph, colouring);
  EXPECT_EQ(colouring.colours.size(), static_cast<std::size_t>(ConstraintColouring::maxColours));
  EXPECT_EQ(colouring.overflow.size(), 30u - ConstraintColouring::maxColours);
}

TEST(ConstraintColouring, SameInputSameColouring) {
  const Graph graph = randomGraph(11, 200, 700, 0.1);
  const ConstraintColouring first = colourConstraints(graph.manifolds, graph.island, graph.movable);
  const ConstraintColouring second = colourConstraints(graph.manifolds, graph.island, graph.movable);
  EXPECT_EQ(first.colours, second.colours);
  EXPECT_EQ(first.overflow, second.overflow);
}

TEST(ConstraintColouring, ColoursASubsetOfManifolds) {
  // An island is a subset of the manifold list: only its manifolds are coloured.
  const Graph graph = randomGraph(3, 100, 300, 0.2);
  std::vector<std::uint32_t> island;
  for (std::uint32_t m = 0; m < graph.manifolds.size(); m += 3) island.push_back(m);
  const ConstraintColouring colouring = colourConstraints(graph.manifolds, island, graph.movable);
  std::vector<std::uint32_t> all = colouring.overflow;
  for (const std::vector<std::uint32_t>& colour : colouring.colours) all.insert(all.end(), colour.begin(), colour.end());
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, island);
}

// Given the island's movable bodies (as the solver has them), the colouring
// is the one that finds them itself; bodies of the list that no manifold
// names change nothing.
TEST(ConstraintColouring, GivenIslandBodiesColourTheSame) {
  for (int seed = 0; seed < 20; ++seed) {
    const Graph graph = randomGraph(static_cast<unsigned>(seed), 80, 250, 0.2);
    std::vector<std::uint32_t> bodies;
    for (std::uint32_t m : graph.island)
      for (std::uint32_t body : {graph.manifolds[m].a, graph.manifolds[m].b})
        if (graph.movable[body]) bodies.push_back(body);
    bodies.push_back(static_cast<std::uint32_t>(graph.movable.size()));  // named by no manifold
    std::sort(bodies.begin(), bodies.end());
    bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
    const ConstraintColouring found = colourConstraints(graph.manifolds, graph.island, graph.movable);
    const ConstraintColouring given = colourConstraints(graph.manifolds, graph.island, graph.movable, bodies);
    EXPECT_EQ(found.colours, given.colours) << "seed " << seed;
    EXPECT_EQ(found.overflow, given.overflow) << "seed " << seed;
  }
}

}  // namespace
}  // namespace physdbg
