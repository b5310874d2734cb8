#pragma once
// The contacts the debugger shows, as opposed to the ones the last step
// solved. A frame can span several steps (--steps-per-frame), a bounce can
// begin and end between two frames, and a sleeping pile rests on contacts no
// step computes any more: a picture of the last step alone would miss all
// three. The history keeps one point per pair and feature (the one that
// pushed hardest), so it stays as small as one step's contacts however many
// steps it covers. Display only: nothing here feeds back into a step.
#include <cstdint>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/contacts/contact_events.h"
#include "engine/contacts/contact_manifold.h"

namespace physdbg {

struct ShownContact {
  BodyPair pair{0, 0};
  std::uint32_t feature = 0;  // manifold feature id; 0 for a one-point contact
  Vec3 point = Vec3::Zero();  // midway between the surfaces, world
  Vec3 normal = Vec3::UnitY();  // from a to b
  double depth = 0.0;  // penetration, m; 0 when held apart
  // The normal impulse the solver applied here over the whole step (every
  // substep its island took, and restitution), N s, so force = impulse / dt;
  // 0 where no solver ran (seed solver, frame 0).
  double impulse = 0.0;
  bool resting = false;  // both bodies asleep or static: a contact no step recomputes
};

// Sorted by (pair, feature), at most one point per key.
class ContactHistory {
 public:
  // Merges one step's points (any order); for a key already held, the point
  // with the larger impulse (then the deeper one) stays.
  void add(std::vector<ShownContact> points);
  void clear() { points_.clear(); }
  const std::vector<ShownContact>& points() const { return points_; }

 private:
  std::vector<ShownContact> points_;
};

// The points of a step's manifolds that touched: within `touching` of each
// other, or pushed apart by the solver (a speculative point whose normal
// impulse is positive stopped a body before it arrived).
std::vector<ShownContact> touchedPoints(const std::vector<ContactManifold>& manifolds, double touching);
// One point per touching pair, for the seed solver.
std::vector<ShownContact> touchedPoints(const std::vector<Contact>& contacts);

// Sorted by key, one per key: the points of `kept` (any order), and those of
// `extra` (sorted, one per key) whose key `kept` lacks.
std::vector<ShownContact> mergeContacts(std::vector<ShownContact> kept, const std::vector<ShownContact>& extra);

// How many distinct pairs the (sorted) points belong to.
int contactPairCount(const std::vector<ShownContact>& points);

}  // namespace physdbg
