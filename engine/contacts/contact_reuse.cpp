#include "engine/contacts/contact_reuse.h"

#include <algorithm>
#include <cmath>

namespace physdbg {
namespace {

// A point fixed to a body that moved from `then` to `now`.
Vec3 carried(const Vec3& point, const Transform& then, const Transform& now) {
  return now.apply(then.applyInverse(point));
}

// The normal turns with body A.
Vec3 carriedNormal(const Vec3& normal, const Transform& then, const Transform& now) {
  return (now.rotation * then.rotation.conjugate() * normal).normalized();
}

}  // namespace

bool worthReusing(const ContactResult& result) { return result.usedBoxBox || result.usedGeneralPath; }

bool carryResult(const ReusableContact& kept, const Transform& a, const Transform& b, ContactResult& result) {
  result = kept.result;
  result.normal = carriedNormal(kept.result.normal, kept.a, a);
  result.pointA = carried(kept.result.pointA, kept.a, a);
  result.pointB = carried(kept.result.pointB, kept.b, b);
  result.gjkIterations = result.epaIterations = 0;
  const double gap = result.normal.dot(result.pointB - result.pointA);
  switch (kept.result.status) {
    case ContactStatus::Separated:
      result.distance = gap;
      return gap > 0.0;
    case ContactStatus::Penetrating:
      result.depth = -gap;
      return gap < 0.0;
    case ContactStatus::Touching:
      return true;
  }
  return false;
}

void carryManifold(const ReusableContact& kept, const Transform& a, const Transform& b, ContactManifold& manifold) {
  manifold = kept.manifold;
  manifold.normal = carriedNormal(kept.manifold.normal, kept.a, a);
  for (int p = 0; p < manifold.pointCount; ++p) {
    ManifoldPoint& point = manifold.points[p];
    point.pointA = a.apply(point.localA);
    point.pointB = b.apply(point.localB);
    point.separation = manifold.normal.dot(point.pointB - point.pointA);
  }
}

const ReusableContact* KeptAnswers::find(const BodyPair& pair) const {
  const auto found = std::lower_bound(current_.begin(), current_.end(), pair,
                                      [](const Entry& entry, const BodyPair& key) { return entry.pair < key; });
  return found != current_.end() && found->pair == pair ? &slots_[found->slot] : nullptr;
}

void KeptAnswers::carry(const BodyPair& pair) {
  while (cursor_ < current_.size() && current_[cursor_].pair < pair) ++cursor_;
  if (cursor_ < current_.size() && current_[cursor_].pair == pair) next_.push_back(current_[cursor_]);
}

// A slot that no current entry uses: one freed by an earlier build, or a new one.
ReusableContact& KeptAnswers::fresh(const BodyPair& pair) {
  std::uint32_t slot;
  if (!free_.empty()) {
    slot = free_.back();
    free_.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  }
  next_.push_back({pair, slot});
  slots_[slot].pair = pair;
  return slots_[slot];
}

void KeptAnswers::endNext() {
  inNext_.assign(slots_.size(), 0);
  for (const Entry& entry : next_) inNext_[entry.slot] = 1;
  for (const Entry& entry : current_)
    if (!inNext_[entry.slot]) free_.push_back(entry.slot);
  current_.swap(next_);
}

}  // namespace physdbg
