#pragma once
// Union-find over body ids, shared by the solver's islands (contact_islands.h)
// and the world's sleep islands, so both group bodies the same way: a set's
// root is its lowest id, which makes the grouping independent of link order.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace physdbg {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0u); }

  // Path halving: each look-up shortens the path it walks.
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  void unite(std::uint32_t x, std::uint32_t y) {
    x = find(x);
    y = find(y);
    if (x != y) parent_[std::max(x, y)] = std::min(x, y);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace physdbg
