#include "engine/solver/resting_load.h"

#include <algorithm>

namespace physdbg {
namespace {

constexpr double supportCosine = 0.70710678118654752;  // 45 degrees from straight up

bool hasImpulse(const ContactManifold& manifold) {
  for (int p = 0; p < manifold.pointCount; ++p)
    if (manifold.points[p].normalImpulse != 0.0) return true;
  return false;
}

struct Support {
  std::uint32_t supported;
  std::uint32_t supporter;
  std::size_t manifold;
  double cosine;  // of the angle between the normal and up
};

// Every manifold on which a movable body rests, grouped by that body
// (counting sort, so one flat array serves all bodies). Bodies are numbered
// by their rank among the supported ones: the table costs what the
// manifolds cost, however many bodies the world holds.
struct SupportTable {
  std::vector<Support> supports;
  std::vector<std::uint32_t> bodies;  // the supported bodies, ascending
  std::vector<std::uint32_t> first;   // supports of bodies[k]: [first[k], first[k + 1])
  std::size_t rank(std::uint32_t id) const {
    return static_cast<std::size_t>(std::lower_bound(bodies.begin(), bodies.end(), id) - bodies.begin());
  }
  bool holds(std::size_t k, std::uint32_t id) const { return k < bodies.size() && bodies[k] == id; }
};

SupportTable findSupports(const std::vector<bool>& movable, const std::vector<ContactManifold>& manifolds,
                          const std::vector<double>& touching, const Vec3& up) {
  std::vector<Support> found;
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    const ContactManifold& manifold = manifolds[m];
    if (touchingPoints(manifold, touching[m]) == 0) continue;
    const double cosine = manifold.normal.dot(up);  // the normal points from a to b
    if (cosine >= supportCosine && movable[manifold.b])
      found.push_back({manifold.b, manifold.a, m, cosine});
    else if (cosine <= -supportCosine && movable[manifold.a])
      found.push_back({manifold.a, manifold.b, m, -cosine});
  }
  SupportTable table;
  for (const Support& support : found) table.bodies.push_back(support.supported);
  std::sort(table.bodies.begin(), table.bodies.end());
  table.bodies.erase(std::unique(table.bodies.begin(), table.bodies.end()), table.bodies.end());
  std::vector<std::uint32_t> ranks(found.size());
  table.first.assign(table.bodies.size() + 1, 0);
  for (std::size_t s = 0; s < found.size(); ++s) {
    ranks[s] = static_cast<std::uint32_t>(table.rank(found[s].supported));
    ++table.first[ranks[s] + 1];
  }
  for (std::size_t k = 0; k < table.bodies.size(); ++k) table.first[k + 1] += table.first[k];
  table.supports.resize(found.size());
  std::vector<std::uint32_t> next(table.first.begin(), table.first.end() - 1);
  for (std::size_t s = 0; s < found.size(); ++s) table.supports[next[ranks[s]]++] = found[s];
  return table;
}

}  // namespace

std::vector<double> restingLoads(const std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                 const std::vector<ContactManifold>& manifolds, const std::vector<double>& touching,
                                 const Vec3& up, const std::vector<std::pair<double, double>>* massScales) {
  std::vector<double> manifoldLoad(manifolds.size(), 0.0);
  if (manifolds.empty()) return manifoldLoad;
  const SupportTable table = findSupports(movable, manifolds, touching, up);
  // Highest first, each body's height measured once; ties keep id order, so
  // the walk is deterministic.
  std::vector<std::pair<double, std::uint32_t>> order;  // height, rank
  for (std::uint32_t k = 0; k < table.bodies.size(); ++k) order.emplace_back(bodies[table.bodies[k]].position().dot(up), k);
  std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  // What each supported body carries; a supporter that rests on nothing
  // passes no load on, so only supported bodies need a slot.
  std::vector<double> carried(table.bodies.size(), 0.0);
  for (const auto& [height, k] : order) {
    const std::uint32_t begin = table.first[k], end = table.first[k + 1];
    const double share = (carried[k] + bodies[table.bodies[k]].mass()) / static_cast<double>(end - begin);
    for (std::uint32_t s = begin; s < end; ++s) {
      const Support& support = table.supports[s];
      manifoldLoad[support.manifold] += share / support.cosine;
      if (!movable[support.supporter]) continue;
      const std::size_t supporter = table.rank(support.supporter);
      if (!table.holds(supporter, support.supporter)) continue;
      double reaching = 1.0;
      if (massScales) {
        const auto& [scaleA, scaleB] = (*massScales)[support.manifold];
        reaching = support.supporter == manifolds[support.manifold].a ? scaleA : scaleB;
      }
      carried[supporter] += share * reaching;
    }
  }
  return manifoldLoad;
}

int touchingPoints(const ContactManifold& manifold, double touching) {
  int count = 0;
  for (int p = 0; p < manifold.pointCount; ++p) count += manifold.points[p].separation <= touching ? 1 : 0;
  return count;
}

void seedNewContact(ContactManifold& manifold, double load, double touching, double gravity, double h) {
  if (load == 0.0 || hasImpulse(manifold)) return;
  const int count = touchingPoints(manifold, touching);
  if (count == 0) return;
  const double impulse = load * gravity * h / count;
  for (int p = 0; p < manifold.pointCount; ++p)
    if (manifold.points[p].separation <= touching) manifold.points[p].normalImpulse = impulse;
}

}  // namespace physdbg
