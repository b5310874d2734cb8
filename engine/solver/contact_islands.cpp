#include "engine/solver/contact_islands.h"

#include <algorithm>

#include "engine/disjoint_sets.h"

namespace physdbg {
namespace {

constexpr std::uint32_t none = ~0u;

}  // namespace

// Two passes, counting then filling, so each island's lists are allocated
// once: this runs every step, for hundreds of small islands.
std::vector<ContactIsland> buildContactIslands(const std::vector<ContactManifold>& manifolds,
                                               const std::vector<bool>& movable) {
  DisjointSets sets(movable.size());
  for (const ContactManifold& manifold : manifolds)
    if (movable[manifold.a] && movable[manifold.b]) sets.unite(manifold.a, manifold.b);
  std::vector<std::uint32_t> islandOf(movable.size(), none);  // by root body
  std::vector<std::uint32_t> manifoldIsland(manifolds.size(), none);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> counts;  // manifolds, bodies
  std::vector<bool> listed(movable.size(), false);
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    const std::uint32_t body = movable[manifold.a] ? manifold.a : manifold.b;
    if (!movable[body]) continue;
    const std::uint32_t root = sets.find(body);
    if (islandOf[root] == none) {
      islandOf[root] = static_cast<std::uint32_t>(counts.size());
      counts.emplace_back(0, 0);
    }
    manifoldIsland[m] = islandOf[root];
    ++counts[islandOf[root]].first;
    for (std::uint32_t id : {manifold.a, manifold.b}) {
      if (!movable[id] || listed[id]) continue;
      listed[id] = true;
      ++counts[islandOf[root]].second;
    }
  }
  std::vector<ContactIsland> islands(counts.size());
  for (std::size_t i = 0; i < islands.size(); ++i) {
    islands[i].manifolds.reserve(counts[i].first);
    islands[i].bodies.reserve(counts[i].second);
  }
  // The fill meets bodies in the same order as the count: it clears each
  // body's mark as it lists it, so each body is listed once.
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    if (manifoldIsland[m] == none) continue;
    ContactIsland& island = islands[manifoldIsland[m]];
    island.manifolds.push_back(m);
    for (std::uint32_t id : {manifolds[m].a, manifolds[m].b}) {
      if (!movable[id] || !listed[id]) continue;
      listed[id] = false;
      island.bodies.push_back(id);
    }
  }
  for (ContactIsland& island : islands) std::sort(island.bodies.begin(), island.bodies.end());
  return islands;
}

}  // namespace physdbg
