#pragma once
// The bodies a step visits, kept as an ascending list (Box2D v3's awake set,
// as a list of ids): present, finite, neither static nor asleep. World
// changes a body's membership only where its state changes (it wakes,
// sleeps, leaves, returns or freezes), so a world of sleeping props costs
// its steps nothing; the list is compacted and sorted on the next read.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace physdbg {

class ActiveBodies {
 public:
  void reserve(std::size_t count) { listed_.reserve(count); }
  void addBody() { listed_.push_back(0); }  // inactive until set

  void set(std::uint32_t id, bool active) {
    if (active == static_cast<bool>(listed_[id])) return;
    listed_[id] = active ? 1 : 0;
    if (active) ids_.push_back(id);  // a leaver stays until the next read drops it
    changed_ = true;
  }

  const std::vector<std::uint32_t>& ids() {
    if (!changed_) return ids_;
    std::erase_if(ids_, [this](std::uint32_t id) { return !listed_[id]; });
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
    changed_ = false;
    return ids_;
  }

 private:
  std::vector<char> listed_;          // per body: active
  std::vector<std::uint32_t> ids_;    // the active ones, ascending once read
  bool changed_ = false;
};

}  // namespace physdbg
