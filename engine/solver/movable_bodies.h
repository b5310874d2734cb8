#pragma once
// The bodies a step moves (dynamic, awake and finite), as a flag per body,
// as an ascending list and as each one's place in that list: a solver visits
// the list, never every body, so sleeping and static bodies cost it nothing,
// and numbers bodies by their place where it needs a table of them (the
// lowest place is the lowest id, so a union-find root stays the lowest id).
#include <cstdint>
#include <utility>
#include <vector>

namespace physdbg {

struct MovableBodies {
  std::vector<bool> flags;          // per body
  std::vector<std::uint32_t> ids;   // the flagged bodies, ascending
  std::vector<std::uint32_t> rank;  // per body: its place in ids; meaningful for flagged bodies only

  MovableBodies() = default;
  // From the flags alone (tests, baselines): lists and ranks them, O(bodies).
  // Implicit on purpose: a flag vector stands for the bodies it flags.
  MovableBodies(std::vector<bool> movable) : flags(std::move(movable)), rank(flags.size(), 0) {  // NOLINT
    for (std::uint32_t id = 0; id < flags.size(); ++id)
      if (flags[id]) {
        rank[id] = static_cast<std::uint32_t>(ids.size());
        ids.push_back(id);
      }
  }
  bool operator[](std::size_t id) const { return flags[id]; }
};

}  // namespace physdbg
