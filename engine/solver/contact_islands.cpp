#include "engine/solver/contact_islands.h"

#include <algorithm>

#include "engine/disjoint_sets.h"

namespace physdbg {
namespace {

constexpr std::uint32_t none = ~0u;

}  // namespace

std::vector<ContactIsland> buildContactIslands(const std::vector<ContactManifold>& manifolds,
                                               const std::vector<bool>& movable) {
  DisjointSets sets(movable.size());
  for (const ContactManifold& manifold : manifolds)
    if (movable[manifold.a] && movable[manifold.b]) sets.unite(manifold.a, manifold.b);
  std::vector<ContactIsland> islands;
  std::vector<std::uint32_t> islandOf(movable.size(), none);  // by root body
  std::vector<bool> listed(movable.size(), false);
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    const std::uint32_t body = movable[manifold.a] ? manifold.a : manifold.b;
    if (!movable[body]) continue;
    const std::uint32_t root = sets.find(body);
    if (islandOf[root] == none) {
      islandOf[root] = static_cast<std::uint32_t>(islands.size());
      islands.emplace_back();
    }
    ContactIsland& island = islands[islandOf[root]];
    island.manifolds.push_back(m);
    for (std::uint32_t id : {manifold.a, manifold.b}) {
      if (!movable[id] || listed[id]) continue;
      listed[id] = true;
      island.bodies.push_back(id);
    }
  }
  for (ContactIsland& island : islands) std::sort(island.bodies.begin(), island.bodies.end());
  return islands;
}

}  // namespace physdbg
