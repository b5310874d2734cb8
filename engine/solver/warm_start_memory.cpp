#include "engine/solver/warm_start_memory.h"

#include <algorithm>

#include "engine/parallel/task_system.h"

namespace physdbg {
namespace {

// cos 8 degrees: a mesh's faces that need manifolds of their own differ by
// more than its active-edge angle (5 degrees) or meet at a concave edge.
constexpr float sameFaceCosine = 0.99f;

}  // namespace

void WarmStartMemory::remember(const std::vector<ContactManifold>& manifolds) {
  manifolds_.clear();
  points_.clear();
  for (const ContactManifold& manifold : manifolds) {
    manifolds_.push_back({{manifold.a, manifold.b},
                          static_cast<std::uint32_t>(points_.size()),
                          static_cast<std::uint32_t>(manifold.pointCount),
                          manifold.normal.cast<float>()});
    for (int p = 0; p < manifold.pointCount; ++p) {
      const ManifoldPoint& point = manifold.points[p];
      points_.push_back({point.localA, point.featureId, point.normalImpulse,
                         {point.tangentImpulse[0], point.tangentImpulse[1]}});
    }
  }
}

// Feature ids first; then each point left over takes the nearest unused old
// point within `reach`. Each old point is carried at most once.
void WarmStartMemory::carry(const Manifold& old, ContactManifold& manifold, double reach) const {
  const Point* oldPoints = points_.data() + old.firstPoint;
  const int oldCount = static_cast<int>(old.pointCount);
  const auto copy = [](const Point& from, ManifoldPoint& to) {
    to.normalImpulse = from.normalImpulse;
    to.tangentImpulse[0] = from.tangentImpulse[0];
    to.tangentImpulse[1] = from.tangentImpulse[1];
  };
  bool used[ContactManifold::maxPoints] = {}, carried[ContactManifold::maxPoints] = {};
  for (int p = 0; p < manifold.pointCount; ++p)
    for (int q = 0; q < oldCount; ++q) {
      if (used[q] || oldPoints[q].featureId != manifold.points[p].featureId) continue;
      copy(oldPoints[q], manifold.points[p]);
      used[q] = carried[p] = true;
      break;
    }
  for (int p = 0; p < manifold.pointCount; ++p) {
    if (carried[p]) continue;
    int nearest = -1;
    double best = reach * reach;
    for (int q = 0; q < oldCount; ++q) {
      const double distance = (oldPoints[q].localA - manifold.points[p].localA).squaredNorm();
      if (!used[q] && distance <= best) {
        best = distance;
        nearest = q;
      }
    }
    if (nearest < 0) continue;
    copy(oldPoints[nearest], manifold.points[p]);
    used[nearest] = true;
  }
}

// Both lists are in pair order, so a range of manifolds walks the remembered
// list from the first one not before its own first pair.
void WarmStartMemory::carryInto(std::vector<ContactManifold>& manifolds, double reach,
                                const TaskSystem* tasks) const {
  const auto carryRange = [&](std::size_t begin, std::size_t end) {
    const BodyPair first{manifolds[begin].a, manifolds[begin].b};
    auto old = std::lower_bound(manifolds_.begin(), manifolds_.end(), first,
                                [](const Manifold& manifold, const BodyPair& pair) { return manifold.pair < pair; });
    for (std::size_t m = begin; m < end; ++m) {
      ContactManifold& manifold = manifolds[m];
      const BodyPair pair{manifold.a, manifold.b};
      while (old != manifolds_.end() && old->pair < pair) ++old;
      if (old == manifolds_.end()) return;
      if (old->pair != pair) continue;
      const auto samePair = [&](std::size_t other) {
        return other < manifolds.size() && manifolds[other].a == manifold.a && manifolds[other].b == manifold.b;
      };
      const bool several = (old + 1 != manifolds_.end() && (old + 1)->pair == pair) || samePair(m + 1) ||
                           (m > 0 && samePair(m - 1));
      if (!several) {
        carry(*old, manifold, reach);
        continue;
      }
      const Eigen::Vector3f normal = manifold.normal.cast<float>();
      auto best = old;
      for (auto candidate = old; candidate != manifolds_.end() && candidate->pair == pair; ++candidate)
        if (candidate->normal.dot(normal) > best->normal.dot(normal)) best = candidate;
      if (best->normal.dot(normal) >= sameFaceCosine) carry(*best, manifold, reach);
    }
  };
  constexpr std::size_t grain = 1024;  // a carry is a few cache lines
  if (manifolds.empty()) return;
  if (tasks)
    tasks->parallelFor(manifolds.size(), grain, carryRange);
  else
    carryRange(0, manifolds.size());
}

}  // namespace physdbg
