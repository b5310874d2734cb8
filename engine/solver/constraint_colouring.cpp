#include "engine/solver/constraint_colouring.h"

#include <algorithm>

namespace physdbg {
namespace {

// One bit per movable body of the island (by its place among them), per colour.
class BodyBits {
 public:
  BodyBits(std::size_t bodies, int colours) : words_((bodies + 63) / 64), bits_(words_ * colours, 0) {}
  bool taken(int colour, std::uint32_t body) const { return (bits_[index(colour, body)] >> (body % 64)) & 1u; }
  void take(int colour, std::uint32_t body) { bits_[index(colour, body)] |= std::uint64_t{1} << (body % 64); }

 private:
  std::size_t index(int colour, std::uint32_t body) const { return colour * words_ + body / 64; }
  std::size_t words_;
  std::vector<std::uint64_t> bits_;
};

constexpr std::uint32_t immovable = ~0u;

}  // namespace

ConstraintColouring colourConstraints(const std::vector<ContactManifold>& all,
                                      const std::vector<std::uint32_t>& manifolds, const std::vector<bool>& movable,
                                      int colourLimit) {
  std::vector<std::uint32_t> bodies;
  bodies.reserve(2 * manifolds.size());
  for (std::uint32_t m : manifolds)
    for (std::uint32_t body : {all[m].a, all[m].b})
      if (movable[body]) bodies.push_back(body);
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  return colourConstraints(all, manifolds, movable, bodies, colourLimit);
}

ConstraintColouring colourConstraints(const std::vector<ContactManifold>& all,
                                      const std::vector<std::uint32_t>& manifolds, const std::vector<bool>& movable,
                                      std::span<const std::uint32_t> bodies, int colourLimit) {
  colourLimit = std::clamp(colourLimit, 0, ConstraintColouring::maxColours);
  // Movable bodies numbered by their rank among the island's movable bodies:
  // a sorted list and a binary search, no hashing (this runs every step).
  const auto local = [&](std::uint32_t body) {
    if (!movable[body]) return immovable;
    return static_cast<std::uint32_t>(std::lower_bound(bodies.begin(), bodies.end(), body) - bodies.begin());
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends(manifolds.size());
  for (std::size_t i = 0; i < manifolds.size(); ++i) ends[i] = {local(all[manifolds[i]].a), local(all[manifolds[i]].b)};

  BodyBits bits(bodies.size(), colourLimit);
  std::vector<std::vector<std::uint32_t>> colours(colourLimit);
  ConstraintColouring result;
  for (std::size_t i = 0; i < manifolds.size(); ++i) {
    const auto [a, b] = ends[i];
    int chosen = -1;
    for (int colour = 0; colour < colourLimit && chosen < 0; ++colour) {
      if ((a != immovable && bits.taken(colour, a)) || (b != immovable && bits.taken(colour, b))) continue;
      chosen = colour;
    }
    if (chosen < 0) {
      result.overflow.push_back(manifolds[i]);
      continue;
    }
    if (a != immovable) bits.take(chosen, a);
    if (b != immovable) bits.take(chosen, b);
    colours[chosen].push_back(manifolds[i]);
  }
  for (std::vector<std::uint32_t>& colour : colours)
    if (!colour.empty()) result.colours.push_back(std::move(colour));
  return result;
}

}  // namespace physdbg
