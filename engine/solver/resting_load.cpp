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
// by their place among the movable ones (MovableBodies::rank): the table
// costs what the movable bodies and manifolds cost, however many bodies the
// world holds.
struct SupportTable {
  std::vector<Support> supports;
  std::vector<std::uint32_t> first;  // supports of movable.ids[k]: [first[k], first[k + 1])
};

SupportTable findSupports(const MovableBodies& movable, const std::vector<ContactManifold>& manifolds,
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
  const std::size_t count = movable.ids.size();
  SupportTable table;
  table.first.assign(count + 1, 0);
  for (const Support& support : found) ++table.first[movable.rank[support.supported] + 1];
  for (std::size_t k = 0; k < count; ++k) table.first[k + 1] += table.first[k];
  table.supports.resize(found.size());
  std::vector<std::uint32_t> next(table.first.begin(), table.first.end() - 1);
  for (const Support& support : found) table.supports[next[movable.rank[support.supported]]++] = support;
  return table;
}

}  // namespace

std::vector<double> restingLoads(const std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                 const std::vector<ContactManifold>& manifolds, const std::vector<double>& touching,
                                 const Vec3& up, const std::vector<std::pair<double, double>>* massScales) {
  std::vector<double> manifoldLoad(manifolds.size(), 0.0);
  if (manifolds.empty()) return manifoldLoad;
  const SupportTable table = findSupports(movable, manifolds, touching, up);
  // Highest first, each body's height measured once; ties keep id order, so
  // the walk is deterministic.
  std::vector<std::pair<double, std::uint32_t>> order;  // height, place
  for (std::uint32_t k = 0; k < movable.ids.size(); ++k)
    if (table.first[k + 1] > table.first[k]) order.emplace_back(bodies[movable.ids[k]].position().dot(up), k);
  std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<double> carried(movable.ids.size(), 0.0);
  for (const auto& [height, k] : order) {
    const std::uint32_t begin = table.first[k], end = table.first[k + 1];
    const double share = (carried[k] + bodies[movable.ids[k]].mass()) / static_cast<double>(end - begin);
    for (std::uint32_t s = begin; s < end; ++s) {
      const Support& support = table.supports[s];
      manifoldLoad[support.manifold] += share / support.cosine;
      if (!movable[support.supporter]) continue;
      double reaching = 1.0;
      if (massScales) {
        const auto& [scaleA, scaleB] = (*massScales)[support.manifold];
        reaching = support.supporter == manifolds[support.manifold].a ? scaleA : scaleB;
      }
      carried[movable.rank[support.supporter]] += share * reaching;
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
