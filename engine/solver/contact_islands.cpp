#include "engine/solver/contact_islands.h"

#include <algorithm>
#include <utility>

#include "engine/disjoint_sets.h"

namespace physdbg {
namespace {

constexpr std::uint32_t none = ~0u;

// Counts into run starts: counts[i] becomes where run i begins, and a last
// entry holds the total.
void countsToStarts(std::vector<std::uint32_t>& counts) {
  std::uint32_t start = 0;
  for (std::uint32_t& count : counts) start += std::exchange(count, start);
  counts.push_back(start);
}

}  // namespace

// Two passes, counting then filling each island's run in place.
void buildContactIslands(const std::vector<ContactManifold>& manifolds, const MovableBodies& movable,
                         ContactIslands& islands) {
  // Bodies are numbered by their place among the movable ones, which keeps
  // the id order: a set's root (its lowest place) is its lowest id.
  const auto local = [&](std::uint32_t id) { return movable.rank[id]; };
  const std::size_t count = movable.ids.size();
  DisjointSets sets(count);
  for (const ContactManifold& manifold : manifolds)
    if (movable[manifold.a] && movable[manifold.b]) sets.unite(local(manifold.a), local(manifold.b));
  islands.islandOf_.assign(count, none);  // by root
  islands.manifoldIsland_.assign(manifolds.size(), none);
  islands.listed_.assign(count, 0);
  std::vector<std::uint32_t>& manifoldStarts = islands.manifoldStarts_;
  std::vector<std::uint32_t>& bodyStarts = islands.bodyStarts_;
  manifoldStarts.clear();
  bodyStarts.clear();
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    const std::uint32_t body = movable[manifold.a] ? manifold.a : manifold.b;
    if (!movable[body]) continue;
    const std::uint32_t root = sets.find(local(body));
    std::uint32_t& island = islands.islandOf_[root];
    if (island == none) {
      island = static_cast<std::uint32_t>(manifoldStarts.size());
      manifoldStarts.push_back(0);
      bodyStarts.push_back(0);
    }
    islands.manifoldIsland_[m] = island;
    ++manifoldStarts[island];
    for (std::uint32_t id : {manifold.a, manifold.b}) {
      if (!movable[id] || islands.listed_[local(id)]) continue;
      islands.listed_[local(id)] = 1;
      ++bodyStarts[island];
    }
  }
  countsToStarts(manifoldStarts);
  countsToStarts(bodyStarts);
  islands.manifolds_.resize(manifoldStarts.back());
  islands.bodies_.resize(bodyStarts.back());
  islands.manifoldFill_.assign(manifoldStarts.begin(), manifoldStarts.end() - 1);
  islands.bodyFill_.assign(bodyStarts.begin(), bodyStarts.end() - 1);
  // The fill meets bodies in the same order as the count: it clears each
  // body's mark as it lists it, so each body is listed once.
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    const std::uint32_t island = islands.manifoldIsland_[m];
    if (island == none) continue;
    islands.manifolds_[islands.manifoldFill_[island]++] = m;
    for (std::uint32_t id : {manifolds[m].a, manifolds[m].b}) {
      if (!movable[id] || !islands.listed_[local(id)]) continue;
      islands.listed_[local(id)] = 0;
      islands.bodies_[islands.bodyFill_[island]++] = id;
    }
  }
  for (std::size_t i = 0; i + 1 < bodyStarts.size(); ++i)
    std::sort(islands.bodies_.begin() + bodyStarts[i], islands.bodies_.begin() + bodyStarts[i + 1]);
}

}  // namespace physdbg
