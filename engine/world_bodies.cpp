// The bodies' storage and state: adding, editing, waking and sleeping,
// leaving and returning, freezing, and the per-body stages of a step
// (forces, kinematic moves). Every per-body loop of a step runs over the
// active bodies (dynamics/active_bodies.h) or a list derived from them, never
// over the world: sleeping and static bodies cost a step nothing.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/parallel/task_system.h"
#include "engine/world.h"

namespace physdbg {
namespace {

constexpr std::size_t bodyGrain = 256;  // a body's forces are cheap: pieces of many

}  // namespace

BodyId World::addBody(const BodyDefinition& definition) {
  bodies_.emplace_back(aboutCentreOfMass(definition));
  const auto id = static_cast<BodyId>(bodies_.size() - 1);
  const RigidBody& body = bodies_.back();
  filtersInUse_ = filtersInUse_ || !body.filter().isDefault();
  // A still kinematic body never moves its proxy; one with a velocity does
  // every step, like an awake dynamic body.
  proxies_.push_back(broadPhase_->addProxy(body.collider().worldBounds(body.transform()), id,
                                           body.isStatic() ? ProxyMotion::Static : ProxyMotion::Dynamic));
  frozen_.push_back(false);
  asleep_.push_back(false);
  present_.push_back(true);
  destroyed_.push_back(false);
  isEdited_.push_back(0);
  movable_.flags.push_back(false);
  movable_.rank.push_back(0);
  islands_.addBody(id);
  active_.addBody();
  updateActivity(id);
  return id;
}

void World::reserveBodies(std::size_t count) {
  bodies_.reserve(count);
  proxies_.reserve(count);
  frozen_.reserve(count);
  asleep_.reserve(count);
  present_.reserve(count);
  destroyed_.reserve(count);
  isEdited_.reserve(count);
  movable_.flags.reserve(count);
  movable_.rank.reserve(count);
  islands_.reserve(count);
  active_.reserve(count);
}

BodyId World::requireLive(BodyId id) const {
  if (id >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(id));
  if (destroyed_[id])
    throw std::invalid_argument("body " + std::to_string(id) + " was destroyed: its id names no body");
  return id;
}

const Aabb& World::fatBox(BodyId id) const {
  if (proxies_.at(id) < 0) throw std::invalid_argument("body " + std::to_string(id) + " has no proxy");
  return broadPhase_->fatBox(proxies_[id]);
}

RigidBody& World::body(BodyId id) {
  RigidBody& body = bodies_[requireLive(id)];
  if (!isEdited_[id]) {
    isEdited_[id] = 1;
    edited_.push_back(id);
  }
  return body;
}

void World::updateActivity(BodyId id) { active_.set(id, takesPart(id) && !bodies_[id].isStatic() && !asleep_[id]); }

const MovableBodies& World::refreshMoving() {
  for (const BodyId id : movable_.ids) movable_.flags[id] = false;
  movable_.ids.clear();
  moving_.clear();
  for (const BodyId id : active_.ids()) {
    if (!isMoving(id)) continue;
    moving_.push_back(id);
    if (bodies_[id].isDynamic()) {
      movable_.flags[id] = true;
      movable_.rank[id] = static_cast<std::uint32_t>(movable_.ids.size());
      movable_.ids.push_back(id);
    }
  }
  return movable_;
}

void World::wakeBody(BodyId id) {
  setAsleep(id, false);
  islands_.resetSlowTime(id);
  if (proxies_[id] >= 0) broadPhase_->setProxyActive(proxies_[id], true);
  updateActivity(id);
  restChanged_ = true;
}

void World::putToSleep(BodyId id) {
  setAsleep(id, true);
  bodies_[id].setLinearVelocity(Vec3::Zero());
  bodies_[id].setAngularVelocity(Vec3::Zero());
  broadPhase_->setProxyActive(proxies_[id], false);
  updateActivity(id);
}

void World::setAsleep(BodyId id, bool asleep) {
  if (asleep_[id] == asleep) return;
  asleep_[id] = asleep;
  if (takesPart(id)) sleepingCount_ += asleep ? 1 : -1;
}

bool World::isMoving(BodyId id) const {
  // The flags first: a sleeping world asks this of every resting contact
  // each step, and the flags spare it a load of each body.
  if (asleep_[id] || !takesPart(id)) return false;
  const RigidBody& body = bodies_[id];
  if (body.isStatic()) return false;
  return !body.isKinematic() || body.linearVelocity() != Vec3::Zero() || body.angularVelocity() != Vec3::Zero();
}

// Wakes come first: a pushed body wakes its whole island, bodies before it
// in id order included, and each of them must then begin the step awake.
void World::applyForces() {
  applyScheduledStates();
  applyScheduledForces();
  wakePushedBodies();
  // Each awake body's forces become its step's accelerations on its own, in parallel.
  const std::vector<BodyId>& active = active_.ids();
  tasks_->parallelFor(active.size(), bodyGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) bodies_[active[k]].beginStep(settings_.gravity);
  });
  stats_.sleepingBodies = sleepingCount_;
  stats_.awakeBodies = static_cast<int>(active.size());
  for (const BodyId id : active)
    if (bodies_[id].hasLocks()) ++stats_.lockedBodies;
}

// In the order they were scheduled, so sums are the same run after run.
void World::applyScheduledForces() {
  for (const ScheduledForce& force : scheduledForces_) {
    if (stepCount_ < force.firstStep || stepCount_ >= force.endStep || !takesPart(force.body)) continue;
    RigidBody& body = this->body(force.body);  // edited: a sleeping body wakes
    if (force.isTorque) body.addTorque(force.vector, force.mode);
    else if (force.at) body.addForceAtPoint(force.vector, *force.at, force.mode);
    else body.addForce(force.vector, force.mode);
  }
}

// Before the forces, so a force of the same step acts on the new state; in
// the order scheduled, so of two changes to one part the later wins. A body
// put somewhere else takes its broad-phase box along (a still kinematic body
// would not move it).
void World::applyScheduledStates() {
  for (const ScheduledState& state : scheduledStates_) {
    if (state.step != stepCount_ || !takesPart(state.body)) continue;
    RigidBody& body = bodies_[state.body];
    if (state.position) body.setPosition(*state.position);
    if (state.orientation) body.setOrientation(*state.orientation);
    if (state.linearVelocity) body.setLinearVelocity(*state.linearVelocity);
    if (state.angularVelocity) body.setAngularVelocity(*state.angularVelocity);
    if (body.isKinematic()) restChanged_ = true;
    wake(state.body);
    if (state.position || state.orientation)
      broadPhase_->moveProxy(proxies_[state.body], body.collider().worldBounds(body.transform()), Vec3::Zero());
  }
}

// A kinematic body moves with its velocities, after the solve: the solvers
// saw it at the start of the step with these velocities (sequential impulses
// also move it through its substeps, so gaps to it stay true).
void World::moveKinematicBodies(const StepContext& context) {
  for (const BodyId id : moving_) {
    if (!bodies_[id].isKinematic()) continue;
    BodyMotion motion = bodies_[id].motion();
    integratePosition(motion, context.dt);
    bodies_[id].setMotion(motion);
  }
}

// A sleeping body that was pushed or given a velocity wakes up. Only an
// edited body (body(id), a scheduled force) can have been: the others are
// as they fell asleep. A kinematic body's new motion may end a rest.
void World::wakePushedBodies() {
  std::sort(edited_.begin(), edited_.end());
  for (const BodyId id : edited_) {
    const RigidBody& body = bodies_[id];
    if (body.isKinematic()) restChanged_ = true;
    if (!asleep_[id] || frozen_[id]) continue;
    if (body.hasPendingForces() || body.linearVelocity() != Vec3::Zero() || body.angularVelocity() != Vec3::Zero())
      wake(id);
  }
}

void World::destroyBody(BodyId id) {
  removeBody(id);
  destroyed_[id] = true;
  std::erase_if(lifetimes_, [id](const BodyLifetime& lifetime) { return lifetime.body == id; });
}

void World::removeBody(BodyId id) {
  requireLive(id);
  if (!present_[id]) return;
  setAsleep(id, false);
  present_[id] = false;
  islands_.makeAlone(id);
  updateActivity(id);
  restChanged_ = true;
  if (proxies_[id] >= 0) broadPhase_->removeProxy(proxies_[id]);
  proxies_[id] = -1;
  // What rested on it falls: its neighbours wake with their islands.
  for (const BodyPair& pair : events_.touchingPairs())
    if (pair.a == id || pair.b == id) wake(pair.a == id ? pair.b : pair.a);
  events_.endPairsWith(id, listener_);
  std::erase_if(resting_, [id](const ShownContact& point) { return point.pair.a == id || point.pair.b == id; });
}

void World::restoreBody(BodyId id) {
  requireLive(id);
  if (present_[id]) return;
  present_[id] = true;
  if (frozen_[id]) return;  // a non-finite body stays out of the broad phase
  updateActivity(id);
  const RigidBody& body = bodies_[id];
  proxies_[id] = broadPhase_->addProxy(body.collider().worldBounds(body.transform()), id,
                                       body.isStatic() ? ProxyMotion::Static : ProxyMotion::Dynamic);
}

// A non-finite body is reported with the step it happened on, then frozen and
// taken out of the broad phase: it cannot poison the tree or other bodies.
void World::freezeNonFiniteBodies() {
  // In id order, so faults are reported in it. Without edited bodies the
  // active list itself (freezing a body only unflags it there).
  std::vector<BodyId> merged;
  if (!edited_.empty()) {
    merged = active_.ids();
    merged.insert(merged.end(), edited_.begin(), edited_.end());
    std::sort(merged.begin(), merged.end());
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
    for (const BodyId id : edited_) isEdited_[id] = 0;
    edited_.clear();
  }
  for (const BodyId id : merged.empty() ? active_.ids() : merged) {
    if (frozen_[id] || bodies_[id].hasFiniteState()) continue;
    if (asleep_[id] && present_[id]) --sleepingCount_;
    frozen_[id] = true;
    updateActivity(id);
    restChanged_ = true;
    if (proxies_[id] >= 0) broadPhase_->removeProxy(proxies_[id]);
    proxies_[id] = -1;
    faults_.push_back({id, stepCount_ + 1, "position, orientation or velocity became NaN or Inf"});
  }
  if (restChanged_ && !moving_.empty()) refreshMoving();  // a frozen body moves no more this step
}

}  // namespace physdbg
