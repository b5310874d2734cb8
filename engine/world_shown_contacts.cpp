// The contacts the debugger shows (engine/contacts/contact_history.h): the history of
// touched points, the points sleeping bodies rest on, and frame 0's contacts
// found without a step. Nothing here changes the simulation.
#include <algorithm>

#include "engine/narrowphase/narrow_phase.h"
#include "engine/world.h"

namespace physdbg {
// A body removed after it touched leaves nothing behind: the frame shows the
// world as it is, and a dot on a body that is not drawn would explain nothing.
// Nor does a body frozen for a non-finite state: the step that broke it may
// have left NaN in its contacts (a recording holds no NaN).
std::vector<ShownContact> World::shownContacts() const {
  if (stepCount_ == 0) return mergeContacts(initialContacts(), resting_);
  std::vector<ShownContact> points =
      mergeContacts(keepHistory_ ? history_.points() : solver_->touchedPoints(contactPass_.contacts()), resting_);
  const auto shown = [this](BodyId id) { return present_[id] && !frozen_[id]; };
  std::erase_if(points, [&](const ShownContact& point) { return !shown(point.pair.a) || !shown(point.pair.b); });
  return points;
}

bool World::atRest(const BodyPair& pair) const {
  const auto still = [this](BodyId id) { return takesPart(id) && !isMoving(id); };
  return still(pair.a) && still(pair.b) && (asleep_[pair.a] || asleep_[pair.b]);
}

// Sleeping proxies make no pairs, so no step recomputes what a sleeping body
// rests on: its points are taken from the step that put it to sleep and
// dropped when a body of the pair wakes (only then are they looked at).
void World::keepRestingContacts(bool fellAsleep) {
  if (resting_.empty() && !fellAsleep) return;  // an awake world: nothing to keep
  if (restChanged_) std::erase_if(resting_, [&](const ShownContact& point) { return !atRest(point.pair); });
  if (!fellAsleep) return;
  std::vector<ShownContact> fresh = solver_->touchedPoints(contactPass_.contacts());
  std::erase_if(fresh, [&](const ShownContact& point) { return !atRest(point.pair); });
  for (ShownContact& point : fresh) point.resting = true;
  resting_ = mergeContacts(std::move(fresh), resting_);
}

// Frame 0 comes before any step: the touching points of the initial state,
// as the first step's narrow phase would find them (within the solver's
// touching gap, static pairs skipped), through a fresh solver of the same
// kind so nothing of this world's changes.
std::vector<ShownContact> World::initialContacts() const {
  const std::unique_ptr<ContactSolver> solver = makeContactSolver(settings_.solver, settings_.narrowPhase);
  const double touching = solver->touchingGap();
  std::vector<Contact> contacts;
  for (const BodyPair& pair : overlappingBoxes(touching)) {
    const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
    const Contact contact{pair.a, pair.b,
                          collide(a.collider(), a.transform(), b.collider(), b.transform(), settings_.narrowPhase)};
    if (contact.result.status == ContactStatus::Separated && contact.result.distance > touching) continue;
    contacts.push_back(contact);
    solver->addCandidate(contact, a, b, touching);
  }
  return solver->touchedPoints(contacts);
}

// Pairs of finite bodies, at least one not static, whose tight boxes grown by
// `margin` overlap: sorted along x and swept, so a scene costs n log n plus
// its neighbours rather than n^2 / 2 tests. Sorted by pair.
std::vector<BodyPair> World::overlappingBoxes(double margin) const {
  std::vector<Aabb> boxes(bodies_.size());
  std::vector<BodyId> order;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (!takesPart(id) || !bodies_[id].hasFiniteState()) continue;
    boxes[id] = bodies_[id].collider().worldBounds(bodies_[id].transform()).enlarged(margin);
    order.push_back(id);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&boxes](BodyId left, BodyId right) { return boxes[left].min.x() < boxes[right].min.x(); });
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const BodyId first = order[i];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min.x() <= boxes[first].max.x(); ++j) {
      const BodyId second = order[j];
      if (bodies_[first].isStatic() && bodies_[second].isStatic()) continue;
      if (boxes[first].overlaps(boxes[second])) pairs.push_back({std::min(first, second), std::max(first, second)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace physdbg
