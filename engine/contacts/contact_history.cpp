#include "engine/contacts/contact_history.h"

#include <algorithm>
#include <tuple>

namespace physdbg {
namespace {

bool keyLess(const ShownContact& left, const ShownContact& right) {
  return std::tie(left.pair, left.feature) < std::tie(right.pair, right.feature);
}

bool sameKey(const ShownContact& left, const ShownContact& right) {
  return left.pair == right.pair && left.feature == right.feature;
}

bool stronger(const ShownContact& candidate, const ShownContact& held) {
  if (candidate.impulse != held.impulse) return candidate.impulse > held.impulse;
  return candidate.depth > held.depth;
}

// Sorts by key and keeps the strongest point of each key.
void sortUnique(std::vector<ShownContact>& points) {
  std::stable_sort(points.begin(), points.end(), keyLess);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (kept > 0 && sameKey(points[kept - 1], points[i])) {
      if (stronger(points[i], points[kept - 1])) points[kept - 1] = points[i];
    } else {
      points[kept++] = points[i];
    }
  }
  points.resize(kept);
}

}  // namespace

void ContactHistory::add(std::vector<ShownContact> points) {
  if (points.empty()) return;
  sortUnique(points);
  std::vector<ShownContact> merged;
  merged.reserve(points_.size() + points.size());
  std::size_t held = 0, fresh = 0;
  while (held < points_.size() || fresh < points.size()) {
    if (fresh == points.size() || (held < points_.size() && keyLess(points_[held], points[fresh]))) {
      merged.push_back(points_[held++]);
    } else if (held == points_.size() || keyLess(points[fresh], points_[held])) {
      merged.push_back(points[fresh++]);
    } else {
      merged.push_back(stronger(points[fresh], points_[held]) ? points[fresh] : points_[held]);
      ++held, ++fresh;
    }
  }
  points_ = std::move(merged);
}

std::vector<ShownContact> touchedPoints(const std::vector<ContactManifold>& manifolds, double touching) {
  std::vector<ShownContact> points;
  for (const ContactManifold& manifold : manifolds) {
    for (int p = 0; p < manifold.pointCount; ++p) {
      const ManifoldPoint& contact = manifold.points[p];
      if (contact.separation > touching && !(contact.normalImpulse > 0.0)) continue;
      points.push_back({{manifold.a, manifold.b},
                        contact.featureId,
                        0.5 * (contact.pointA + contact.pointB),
                        manifold.normal,
                        std::max(0.0, -contact.separation),
                        contact.stepNormalImpulse,  // the whole step's, so force = impulse / dt
                        false});
    }
  }
  return points;
}

std::vector<ShownContact> touchedPoints(const std::vector<Contact>& contacts) {
  std::vector<ShownContact> points;
  points.reserve(contacts.size());
  for (const Contact& contact : contacts) {
    const ContactResult& result = contact.result;
    points.push_back(
        {{contact.a, contact.b}, 0, 0.5 * (result.pointA + result.pointB), result.normal, result.depth, 0.0, false});
  }
  return points;
}

std::vector<ShownContact> mergeContacts(std::vector<ShownContact> kept, const std::vector<ShownContact>& extra) {
  sortUnique(kept);
  const std::size_t keptCount = kept.size();
  for (const ShownContact& point : extra) {
    if (!std::binary_search(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(keptCount), point, keyLess))
      kept.push_back(point);
  }
  std::inplace_merge(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(keptCount), kept.end(), keyLess);
  return kept;
}

int contactPairCount(const std::vector<ShownContact>& points) {
  int count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0 || points[i].pair != points[i - 1].pair) ++count;
  }
  return count;
}

}  // namespace physdbg
