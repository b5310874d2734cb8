#pragma once
// Bullet's dynamic tree (btDbvt) and broad phase (btDbvtBroadphase) fed the
// same boxes as ours. Without Bullet every entry point says so by returning
// nothing; Bullet's headers stay inside tree_bullet_peer.cpp.
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "engine/aabb.h"

namespace physdbg::bench {

bool bulletAvailable();

struct PeerTreeFigures {
  double insertMs = 0.0;
  double removeMs = 0.0;
  double internalArea = 0.0;
  double sar = 0.0;
  int height = 0;
};

// Inserts the boxes one by one into a btDbvt, measures it, then removes them in `removalOrder`
// (empty: keep them).
std::optional<PeerTreeFigures> bulletDbvtInsertRemove(const std::vector<Aabb>& boxes,
                                                      const std::vector<int>& removalOrder);

class BulletBroadPhasePeer {
 public:
  // nullptr without Bullet.
  static std::unique_ptr<BulletBroadPhasePeer> create(const std::vector<Aabb>& boxes);
  virtual ~BulletBroadPhasePeer() = default;
  // setAabb for every proxy, then calculateOverlappingPairs; returns its milliseconds.
  virtual double step(const std::vector<Aabb>& boxes) = 0;
  // Box index pairs currently in Bullet's pair cache.
  virtual std::vector<std::pair<int, int>> pairs() const = 0;
};

}  // namespace physdbg::bench
