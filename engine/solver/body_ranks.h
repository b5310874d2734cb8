#pragma once
// The bodies of a step's manifolds numbered by rank (ascending id), so the
// solver's per-body tables hold those bodies only: a world of 100,000
// sleeping props and a few moving bodies sizes them for the few. A table is
// still indexed by body id (RankedTable::operator[]); the SIMD kernels, which
// gather bodies lane by lane, take the dense storage and ranks directly.
#include <cstdint>
#include <span>
#include <vector>

namespace physdbg {

class BodyRanks {
 public:
  // `ids` ascending; `bodyCount` bounds every id.
  void assign(std::span<const std::uint32_t> ids, std::size_t bodyCount) {
    rankOf_.resize(bodyCount);
    for (std::size_t k = 0; k < ids.size(); ++k) rankOf_[ids[k]] = static_cast<std::uint32_t>(k);
    count_ = ids.size();
  }
  std::uint32_t operator()(std::uint32_t id) const { return rankOf_[id]; }
  std::size_t size() const { return count_; }

 private:
  std::vector<std::uint32_t> rankOf_;  // per body; meaningful for the ranked ones only
  std::size_t count_ = 0;
};

template <typename T>
class RankedTable {
 public:
  // Sized for the ranks' current bodies; entries keep nothing across a resize.
  void resize(const BodyRanks& ranks) {
    ranks_ = &ranks;
    items_.resize(ranks.size());
  }
  T& operator[](std::uint32_t id) { return items_[(*ranks_)(id)]; }
  const T& operator[](std::uint32_t id) const { return items_[(*ranks_)(id)]; }
  std::vector<T>& byRank() { return items_; }
  const std::vector<T>& byRank() const { return items_; }
  std::size_t size() const { return items_.size(); }

 private:
  const BodyRanks* ranks_ = nullptr;  // set by resize, once a step, before any look-up
  std::vector<T> items_;
};

}  // namespace physdbg
