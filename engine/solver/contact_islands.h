#pragma once
// Islands: groups of movable bodies linked by contact manifolds. Static,
// sleeping and frozen bodies do not link (they do not move, so bodies resting
// on the same floor are independent). Each island is solved on its own, with
// its own stiffness and substeps: a heavy box on a light one makes its own
// pile take more substeps, not the whole world.
#include <cstdint>
#include <vector>

#include "engine/contacts/contact_manifold.h"

namespace physdbg {

struct ContactIsland {
  std::vector<std::uint32_t> manifolds;  // indices into the manifold list, ascending
  std::vector<std::uint32_t> bodies;     // movable bodies, ascending
};

// Islands in the order of their lowest manifold index; a manifold between two
// bodies that are both immovable belongs to none. Deterministic.
std::vector<ContactIsland> buildContactIslands(const std::vector<ContactManifold>& manifolds,
                                               const std::vector<bool>& movable);

}  // namespace physdbg
