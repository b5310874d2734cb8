#include "engine/sleep/sleep_islands.h"

#include <algorithm>
#include <limits>

#include "engine/disjoint_sets.h"

namespace physdbg {

void SleepIslands::reserve(std::size_t count) {
  slowTime_.reserve(count);
  island_.reserve(count);
}

void SleepIslands::addBody(std::uint32_t id) {
  slowTime_.resize(std::max<std::size_t>(slowTime_.size(), id + 1), 0.0);
  island_.resize(std::max<std::size_t>(island_.size(), id + 1));
  makeAlone(id);
}

void SleepIslands::makeAlone(std::uint32_t id) {
  island_[id] = id;
  slowTime_[id] = 0.0;
}

// Bodies are numbered by their place among the movable ones (ascending, so
// a set's root, its lowest place, is its lowest id).
void SleepIslands::link(const std::vector<Contact>& contacts, const MovableBodies& movable) {
  const std::vector<std::uint32_t>& ids = movable.ids;
  DisjointSets sets(ids.size());
  for (const Contact& contact : contacts)
    if (movable[contact.a] && movable[contact.b]) sets.unite(movable.rank[contact.a], movable.rank[contact.b]);
  for (std::size_t k = 0; k < ids.size(); ++k) island_[ids[k]] = ids[sets.find(static_cast<std::uint32_t>(k))];
}

void SleepIslands::findSleepers(const std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                const SleepSettings& settings, double dt, std::vector<Sleeper>& sleepers) {
  sleepers.clear();
  const std::vector<std::uint32_t>& ids = movable.ids;
  for (const std::uint32_t id : ids) {
    const RigidBody& body = bodies[id];
    const bool slow = body.linearVelocity().norm() < settings.linearSpeed &&
                      body.angularVelocity().norm() < settings.angularSpeed;
    slowTime_[id] = slow ? slowTime_[id] + dt : 0.0;
  }
  if (!settings.allowSleep) return;
  std::vector<double> islandSlowTime(ids.size(), std::numeric_limits<double>::infinity());  // by the root's rank
  std::vector<std::uint32_t> islandSize(ids.size(), 0);
  for (const std::uint32_t id : ids) {
    const std::uint32_t root = movable.rank[island_[id]];
    islandSlowTime[root] = std::min(islandSlowTime[root], slowTime_[id]);
    ++islandSize[root];
  }
  for (const std::uint32_t id : ids) {
    const std::uint32_t root = movable.rank[island_[id]];
    if (islandSlowTime[root] < settings.timeToSleep) continue;
    const bool alone = islandSize[root] == 1;
    if (!alone) sleeping_[island_[id]].push_back(id);
    sleepers.push_back({id, alone});
  }
}

std::vector<std::uint32_t> SleepIslands::takeIsland(std::uint32_t label) {
  const auto found = sleeping_.find(label);
  if (found == sleeping_.end()) return {};
  std::vector<std::uint32_t> members = std::move(found->second);
  sleeping_.erase(found);
  std::sort(members.begin(), members.end());
  return members;
}

bool closesOnSleeper(const ContactManifold& manifold, const RigidBody& mover, bool moverIsA, double dt,
                     double touchingGap) {
  // The normal points from a to b; towards the sleeper is -normal for b.
  const Vec3 towards = moverIsA ? manifold.normal : Vec3(-manifold.normal);
  const double gain = mover.stepAcceleration().norm() * dt;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    const Vec3 at = moverIsA ? point.pointA : point.pointB;
    const Vec3 velocity = mover.linearVelocity() + mover.angularVelocity().cross(at - mover.position());
    const double closing = std::max(0.0, velocity.dot(towards)) + gain;
    if (closing * dt >= point.separation - touchingGap) return true;
  }
  return false;
}

}  // namespace physdbg
