#pragma once
// Islands: groups of movable bodies linked by contact manifolds. Static,
// sleeping and frozen bodies do not link (they do not move, so bodies resting
// on the same floor are independent). Each island is solved on its own, with
// its own stiffness and substeps: a heavy box on a light one makes its own
// pile take more substeps, not the whole world.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/contacts/contact_manifold.h"
#include "engine/solver/movable_bodies.h"

namespace physdbg {

// One island's lists, viewed where they are stored.
struct ContactIsland {
  std::span<const std::uint32_t> manifolds;  // indices into the manifold list, ascending
  std::span<const std::uint32_t> bodies;     // movable bodies, ascending
};

// Every island's lists end to end: a thousand boxes resting apart on a floor
// are a thousand islands, rebuilt every step, and two lists of their own
// each were two thousand allocations a step. Kept by the solver from step to
// step, so the storage is reused too.
class ContactIslands {
 public:
  std::size_t size() const { return manifoldStarts_.empty() ? 0 : manifoldStarts_.size() - 1; }
  ContactIsland operator[](std::size_t i) const {
    return {std::span(manifolds_).subspan(manifoldStarts_[i], manifoldStarts_[i + 1] - manifoldStarts_[i]),
            std::span(bodies_).subspan(bodyStarts_[i], bodyStarts_[i + 1] - bodyStarts_[i])};
  }

 private:
  friend void buildContactIslands(const std::vector<ContactManifold>&, const MovableBodies&, ContactIslands&);
  std::vector<std::uint32_t> manifolds_, bodies_;
  std::vector<std::uint32_t> manifoldStarts_, bodyStarts_;  // island i's run, then the end
  // Scratch of the build, kept for its capacity.
  // By the bodies' place among the movable ones (MovableBodies::rank), so a
  // build costs what the movable bodies and manifolds cost, whatever the
  // number of bodies.
  std::vector<std::uint32_t> islandOf_, manifoldIsland_, manifoldFill_, bodyFill_;
  std::vector<char> listed_;
};

// Islands in the order of their lowest manifold index; a manifold between two
// bodies that are both immovable belongs to none. Deterministic.
void buildContactIslands(const std::vector<ContactManifold>& manifolds, const MovableBodies& movable,
                         ContactIslands& islands);

}  // namespace physdbg
