#pragma once
// Graph colouring of an island's contact manifolds (as in Box2D v3's
// constraint graph): manifolds of one colour share no movable body, so a
// colour's manifolds can be solved in any order, side by side in SIMD lanes
// or on several threads, and each still sees exactly the body velocities it
// would see alone. Immovable bodies (static, kinematic, asleep) take no
// impulse, so they do not count: every box on the floor may share a colour.
//
// Greedy, in manifold order: each manifold takes the first colour where
// neither of its movable bodies is taken yet. A bounded number of colours
// keeps each one full; what fits none (a body with more contacts than
// colours) goes to the overflow, solved one by one after the colours. The
// result depends only on the manifold order, never on threads.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/contacts/contact_manifold.h"

namespace physdbg {

struct ConstraintColouring {
  static constexpr int maxColours = 24;
  // Manifold indices (into the solver's list) of each colour, in island
  // order; empty colours are dropped, so colours.size() <= maxColours.
  std::vector<std::vector<std::uint32_t>> colours;
  std::vector<std::uint32_t> overflow;  // in island order
};

// `manifolds` is an island's manifold list (indices into `all`, ascending);
// `movable[i]` false: body i is immovable this step and shared freely.
ConstraintColouring colourConstraints(const std::vector<ContactManifold>& all,
                                      const std::vector<std::uint32_t>& manifolds, const std::vector<bool>& movable,
                                      int colourLimit = ConstraintColouring::maxColours);
// The same, given the island's movable bodies (every movable body of its
// manifolds, ascending, as ContactIsland::bodies holds them): the solver has
// them already, and sorting them again was a tenth of a sphere pile's
// colouring.
ConstraintColouring colourConstraints(const std::vector<ContactManifold>& all,
                                      const std::vector<std::uint32_t>& manifolds, const std::vector<bool>& movable,
                                      std::span<const std::uint32_t> islandBodies,
                                      int colourLimit = ConstraintColouring::maxColours);

}  // namespace physdbg
