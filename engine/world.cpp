#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/broadphase/brute_force_broad_phase.h"
#include "engine/broadphase/tree_broad_phase.h"
#include "engine/disjoint_sets.h"
#include "engine/contacts/manifold_builder.h"
#include "engine/narrowphase/linear_cast.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/parallel/task_system.h"
#include "engine/stage_timer.h"

namespace physdbg {
namespace {

// Indices per piece of a parallel loop: enough work that a piece outweighs
// handing it to a thread, about 10 us on the cheap side (handing over costs
// several us here, and the bodies' cache lines follow the piece). Screening
// a pair is 10-20 ns; a near pair runs the narrow phase, 0.05 us for two
// spheres to several us for GJK and EPA; a body's prediction is ~0.1 us.
// A small scene's pair loops therefore stay on the calling thread.
constexpr std::size_t pairGrain = 1024;
constexpr std::size_t nearPairGrain = 128;
constexpr std::size_t bodyGrain = 256;
constexpr std::size_t staticRowGrain = 8;  // a row is up to n overlap tests

// A body's tight box grown by its reach share and padded well past the
// rounding of the exact test (which grows one box by the pair's reach), so
// pairs that miss here also miss there: the outcome is the same either way.
// A share that is not finite grows the box to everything and leaves the
// pair to the exact test.
Aabb paddedReachBounds(const Aabb& tight, double share) {
  const double size = std::max(tight.min.cwiseAbs().maxCoeff(), tight.max.cwiseAbs().maxCoeff());
  const double padded = share + 1e-9 * (1.0 + share + size);
  if (!(std::isfinite(padded)))
    return {Vec3::Constant(-std::numeric_limits<double>::infinity()),
            Vec3::Constant(std::numeric_limits<double>::infinity())};
  return tight.enlarged(padded);
}

std::unique_ptr<BroadPhase> makeBroadPhase(const WorldSettings& settings, const TaskSystem& tasks,
                                           CollisionOffload* offload) {
  if (settings.broadPhase == BroadPhaseKind::BruteForce) {
    BruteForceOptions options;
    options.margin = settings.fatMargin;
    options.checkBothOrders = settings.bruteForceBothOrders;
    options.tasks = &tasks;
    return std::make_unique<BruteForceBroadPhase>(options);
  }
  DynamicAabbTreeOptions options;
  options.margin = settings.fatMargin;
  options.insertion = settings.treeInsertion;
  options.rotations = settings.treeRotations;
  if (offload != nullptr) return offload->makeBroadPhase(options);
  return std::make_unique<TreeBroadPhase>(options, &tasks);
}

}  // namespace

World::World(const WorldSettings& settings, std::shared_ptr<CollisionOffload> offload)
    : settings_(settings),
      tasks_(std::make_unique<TaskSystem>(settings.threads)),
      offload_(std::move(offload)),
      broadPhase_(makeBroadPhase(settings, *tasks_, offload_.get())),
      solver_(makeContactSolver(settings.solver, settings.narrowPhase)) {
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt)) throw std::invalid_argument("dt must be positive");
  if (!isFinite(settings.gravity)) throw std::invalid_argument("gravity must be finite");
  if (!(settings.fatMargin >= 0.0)) throw std::invalid_argument("fat margin must not be negative");
  if (settings.collisionDevice == CollisionDevice::Gpu && offload_ == nullptr)
    throw std::invalid_argument("collision on the gpu needs a compute context, which the engine cannot make: "
                                "physdbg simulate, render, contacts and bench make one (--collision gpu); "
                                "a program passes a gpu::GpuCollision");
  if (settings.collisionDevice == CollisionDevice::Cpu && offload_ != nullptr)
    throw std::invalid_argument("a collision offload was given to a world whose collision device is cpu");
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::addBody(const BodyDefinition& definition) {
  bodies_.emplace_back(aboutCentreOfMass(definition));
  const auto id = static_cast<BodyId>(bodies_.size() - 1);
  const RigidBody& body = bodies_.back();
  proxies_.push_back(broadPhase_->addProxy(body.collider().worldBounds(body.transform()), id,
                                           body.isStatic() ? ProxyMotion::Static : ProxyMotion::Dynamic));
  // A still kinematic body never moves its proxy; one with a velocity does
  // every step, like an awake dynamic body.
  frozen_.push_back(false);
  asleep_.push_back(false);
  present_.push_back(true);
  slowTime_.push_back(0.0);
  island_.push_back(id);
  inActive_.push_back(0);
  isEdited_.push_back(0);
  movable_.flags.push_back(false);
  updateActivity(id);
  return id;
}

void World::reserveBodies(std::size_t count) {
  bodies_.reserve(count);
  proxies_.reserve(count);
  frozen_.reserve(count);
  asleep_.reserve(count);
  present_.reserve(count);
  slowTime_.reserve(count);
  island_.reserve(count);
  inActive_.reserve(count);
  isEdited_.reserve(count);
  movable_.flags.reserve(count);
}

RigidBody& World::body(BodyId id) {
  RigidBody& body = bodies_.at(id);
  if (!isEdited_[id]) {
    isEdited_[id] = 1;
    edited_.push_back(id);
  }
  return body;
}

void World::updateActivity(BodyId id) {
  const bool active = takesPart(id) && !bodies_[id].isStatic() && !asleep_[id];
  if (active == static_cast<bool>(inActive_[id])) return;
  inActive_[id] = active ? 1 : 0;
  if (active) active_.push_back(id);
  activeChanged_ = true;
}

const std::vector<BodyId>& World::activeBodies() {
  if (!activeChanged_) return active_;
  std::erase_if(active_, [this](BodyId id) { return !inActive_[id]; });
  std::sort(active_.begin(), active_.end());
  active_.erase(std::unique(active_.begin(), active_.end()), active_.end());
  activeChanged_ = false;
  return active_;
}

const MovableBodies& World::refreshMoving() {
  for (const BodyId id : movable_.ids) movable_.flags[id] = false;
  movable_.ids.clear();
  moving_.clear();
  for (const BodyId id : activeBodies()) {
    if (!isMoving(id)) continue;
    moving_.push_back(id);
    if (bodies_[id].isDynamic()) {
      movable_.flags[id] = true;
      movable_.ids.push_back(id);
    }
  }
  return movable_;
}

int World::threadCount() const { return tasks_->threadCount(); }

const DynamicAabbTree* World::tree() const {
  const auto* tree = dynamic_cast<const TreeBroadPhase*>(broadPhase_.get());
  return tree ? &tree->tree() : nullptr;
}

// The order of a step, as the design describes it. When velocities are
// integrated differs by solver: the seed solver integrates them in beginStep
// (the design's order), sequential impulses inside its substeps.
void World::step() {
  stats_ = StepStats{};
  StepProfile& profile = stats_.profile;
  const StageTimer whole(profile.total);
  const StepContext context{settings_.dt, settings_.gravity, tasks_.get()};
  {
    const StageTimer timer(profile.forces);
    applyForces();  // gravity, user forces and impulses
    solver_->beginStep(bodies_, refreshMoving(), context);
    freezeNonFiniteBodies();
  }
  {
    const StageTimer timer(profile.broadPhase);
    updateBroadPhase(context);  // fat boxes follow the bodies that moved
  }
  findContacts(context);  // candidate pairs, then the narrow phase on each
  // A body woken by a touch had no pairs with what else it rests on (asleep,
  // its proxy made none): find them before solving, or it would fall a step.
  while (wakeTouchedBodies(context)) findContacts(context);
  // After the last pass: a second pass must find what the first found (the
  // last step's answers), or a wake would change pairs it never touched.
  keepAnswers();
  solveContacts(context);  // responses, then positions
  const StageTimer timer(profile.afterSolve);
  moveKinematicBodies(context);
  events_.update(solver_->eventContacts(contacts_), [this](const BodyPair& pair) { return atRest(pair); },
                 restChanged_, listener_);
  if (keepHistory_) history_.add(solver_->touchedPoints(contacts_));
  linkIslands();
  keepRestingContacts(updateSleep(context));
  freezeNonFiniteBodies();
  applyLifetimes(stepCount_ + 1);  // the state this step ends in has the bodies it should
  restChanged_ = false;
  ++stepCount_;
}

// An island fell asleep together, so it wakes together: a body left asleep
// beside a woken neighbour would hold no contacts with it (sleeping proxies
// make no pairs) until the next touch woke it a step late.
void World::wake(BodyId id) {
  if (!asleep_.at(id)) return;
  const BodyId island = island_[id];
  const auto found = sleepingIslands_.find(island);
  if (found == sleepingIslands_.end()) {  // alone: only islands of several bodies are listed
    wakeBody(id);
    return;
  }
  std::vector<BodyId> members = std::move(found->second);
  sleepingIslands_.erase(found);
  // In id order; a member listed twice, removed or asleep elsewhere since is
  // no longer this island's.
  std::sort(members.begin(), members.end());
  for (const BodyId member : members)
    if (asleep_[member] && island_[member] == island) wakeBody(member);
}

void World::wakeBody(BodyId id) {
  setAsleep(id, false);
  slowTime_[id] = 0.0;
  if (proxies_[id] >= 0) broadPhase_->setProxyActive(proxies_[id], true);
  updateActivity(id);
  restChanged_ = true;
}

void World::putToSleep(BodyId id, bool alone) {
  setAsleep(id, true);
  if (!alone) sleepingIslands_[island_[id]].push_back(id);
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

void World::sleep(BodyId id) {
  if (id >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(id));
  if (!bodies_[id].isDynamic())
    throw std::invalid_argument("body " + std::to_string(id) + " is static or kinematic: only a dynamic body sleeps");
  if (!takesPart(id))
    throw std::invalid_argument("body " + std::to_string(id) + " is absent or frozen: it cannot sleep");
  if (asleep_[id]) return;
  island_[id] = id;  // alone: waking it wakes no other body
  putToSleep(id, true);
}

bool World::isMoving(BodyId id) const {
  // The flags first: a sleeping world asks this of every resting contact
  // each step, and the flags spare it a load of each body.
  if (asleep_[id] || !takesPart(id)) return false;
  const RigidBody& body = bodies_[id];
  if (body.isStatic()) return false;
  return !body.isKinematic() || body.linearVelocity() != Vec3::Zero() || body.angularVelocity() != Vec3::Zero();
}

void World::scheduleForce(const ScheduledForce& force) {
  if (force.body >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(force.body));
  if (!bodies_[force.body].isDynamic())
    throw std::invalid_argument("body " + std::to_string(force.body) + " is static or kinematic: forces cannot move it");
  if (force.isTorque && force.at) throw std::invalid_argument("a torque has no point of application");
  if (!isFinite(force.vector) || (force.at && !isFinite(*force.at)))
    throw std::invalid_argument("force vector and point must be finite");
  if (!(0 <= force.firstStep && force.firstStep < force.endStep))
    throw std::invalid_argument("force steps must be A < B with A >= 0");
  scheduledForces_.push_back(force);
}

void World::scheduleState(const ScheduledState& state) {
  if (state.body >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(state.body));
  if (bodies_[state.body].isStatic())
    throw std::invalid_argument("body " + std::to_string(state.body) + " is static: its state cannot be set");
  if (!state.position && !state.orientation && !state.linearVelocity && !state.angularVelocity)
    throw std::invalid_argument("nothing to set: give a position, orientation, velocity or angular velocity");
  const auto finite = [](const std::optional<Vec3>& v) { return !v || isFinite(*v); };
  if (!finite(state.position) || !finite(state.linearVelocity) || !finite(state.angularVelocity) ||
      (state.orientation && !isFinite(*state.orientation)))
    throw std::invalid_argument("state values must be finite");
  if (state.orientation && !(state.orientation->norm() >= 1e-12))
    throw std::invalid_argument("orientation is a zero quaternion");
  if (state.step < stepCount_) throw std::invalid_argument("step " + std::to_string(state.step) + " has passed");
  scheduledStates_.push_back(state);
}

// Wakes come first: a pushed body wakes its whole island, bodies before it
// in id order included, and each of them must then begin the step awake.
void World::applyForces() {
  applyScheduledStates();
  applyScheduledForces();
  wakePushedBodies();
  // Each awake body's forces become its step's accelerations on its own, in parallel.
  const std::vector<BodyId>& active = activeBodies();
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

// Each moving body's box is predicted in parallel; the broad phase's edits
// stay serial, in body order, so the tree is the same for any thread count.
void World::updateBroadPhase(const StepContext& context) {
  predictions_.resize(moving_.size());  // by place in moving_
  tasks_->parallelFor(moving_.size(), bodyGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) predictions_[k] = solver_->predictMotion(bodies_[moving_[k]], context);
  });
  for (std::size_t k = 0; k < moving_.size(); ++k)
    broadPhase_->moveProxy(proxies_[moving_[k]], predictions_[k].box, predictions_[k].displacement);
}

void World::findContacts(const StepContext& context) {
  StepProfile& profile = stats_.profile;
  {
    const StageTimer timer(profile.pairs);
    broadPhase_->findPairs(pairs_);
  }
  stats_.broadPhase = broadPhase_->stats();
  stats_.candidatePairs = static_cast<int>(pairs_.size());
  contacts_.clear();
  solver_->clearContacts();
  {
    const StageTimer timer(profile.narrowPhase);
    testPairs(context);
  }
  {
    const StageTimer timer(profile.manifolds);
    gatherContacts(context);
  }
  stats_.manifolds = static_cast<int>(solver_->manifolds().size());
  if (!settings_.skipStaticPairs) {
    const StageTimer timer(profile.narrowPhase);
    testStaticPairs();
  }
  stats_.contacts = static_cast<int>(contacts_.size());
}

// Fat boxes overlap long before the shapes can touch: when even the tight
// boxes, grown by how far the pair can close this step, stay apart, the
// narrow phase has nothing to say. Most pairs miss by more than the two
// bodies' reach shares, which settles them without the pair's own reach.
World::PairOutcome World::screenPair(const BodyPair& pair, const StepContext& context) const {
  // A kinematic body passes through static ones. (Dense per-body flags: most
  // pairs end at the bounds, and need not touch the bodies themselves.)
  const MeasuredBody &a = measured(pair.a), &b = measured(pair.b);
  if (!a.dynamic && !b.dynamic) return PairOutcome::Skipped;
  if (!a.reachBounds.overlaps(b.reachBounds)) return PairOutcome::BoundsRejected;
  const double reach = solver_->contactReach(a.reach, b.reach, context);
  if (!a.tight.enlarged(reach).overlaps(b.tight)) return PairOutcome::BoundsRejected;
  return PairOutcome::Near;
}

// Writes into `answer` in place.
World::PairOutcome World::answerPair(const BodyPair& pair, const StepContext& context, PairAnswer& answer) const {
  const double reach = solver_->contactReach(measured(pair.a).reach, measured(pair.b).reach, context);
  answer.reach = reach;
  answer.kept = nullptr;
  const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
  if (offload_ && offload_->handles(a.collider().kind(), b.collider().kind()) && !settings_.bruteForceBothOrders)
    return PairOutcome::Offloaded;
  if (reusesContacts()) {
    const ReusableContact* kept = kept_.find(pair);
    if (kept && stillHolds(*kept, a.transform(), b.transform(), ContactReuseTolerance{}) &&
        carryResult(*kept, a.transform(), b.transform(), answer.result)) {
      answer.kept = kept;
      return PairOutcome::Tested;
    }
  }
  answer.result = collide(a.collider(), a.transform(), b.collider(), b.transform(), settings_.narrowPhase);
  // The design's brute force ran the narrow phase for B-A too; it responded
  // once per pair, so that second answer is only counted (gatherContacts).
  if (settings_.bruteForceBothOrders)
    answer.reversed = collide(b.collider(), b.transform(), a.collider(), a.transform(), settings_.narrowPhase);
  return PairOutcome::Tested;
}

// What screenPair and answerPair need of each body of a candidate pair
// alone, once per body: a body meets many pairs. Bodies do not move between
// the passes of a step, but a pass after a wake has other pairs, so each pass
// measures anew.
// Stored densely, in the order the pairs meet the bodies (pairPlace_), so
// the tables grow with the bodies in pairs, not with the world.
void World::measureBodies(const StepContext& context) {
  pairPlace_.resize(bodies_.size(), notInPair);
  for (const BodyId id : pairBodies_) pairPlace_[id] = notInPair;
  pairBodies_.clear();
  for (const BodyPair& pair : pairs_)
    for (const BodyId id : {pair.a, pair.b})
      if (pairPlace_[id] == notInPair) {
        pairPlace_[id] = static_cast<std::uint32_t>(pairBodies_.size());
        pairBodies_.push_back(id);
      }
  measured_.resize(pairBodies_.size());
  tasks_->parallelFor(pairBodies_.size(), bodyGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const RigidBody& body = bodies_[pairBodies_[k]];
      MeasuredBody& measured = measured_[k];
      measured.dynamic = body.isDynamic();
      measured.tight = body.collider().worldBounds(body.transform());
      measured.reach = solver_->bodyReach(body, context);
      measured.reachBounds = paddedReachBounds(measured.tight, solver_->reachShare(measured.reach, context));
    }
  });
}

void World::testPairs(const StepContext& context) {
  measureBodies(context);
  pairOutcomes_.resize(pairs_.size());
  tasks_->parallelFor(pairs_.size(), pairGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) pairOutcomes_[i] = screenPair(pairs_[i], context);
  });
  nearPairs_.clear();
  for (std::size_t i = 0; i < pairs_.size(); ++i)
    if (pairOutcomes_[i] == PairOutcome::Near) nearPairs_.push_back(static_cast<std::uint32_t>(i));
  pairAnswers_.resize(nearPairs_.size());
  tasks_->parallelFor(nearPairs_.size(), nearPairGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = nearPairs_[k];
      pairOutcomes_[i] = answerPair(pairs_[i], context, pairAnswers_[k]);
    }
  });
  if (offload_) testOffloadedPairs();
  if (settings_.castFastPairs) castFastPairs(context);
}

// How far a body moves over the step, as the broad phase predicts it.
Vec3 World::stepMotion(BodyId id, const StepContext& context) const {
  if (!isMoving(id)) return Vec3::Zero();
  const RigidBody& body = bodies_[id];
  return (body.linearVelocity() + body.stepAcceleration() * context.dt) * context.dt;
}

// Pairs apart now that close by more than a quarter of the smaller body's
// smallest extent this step (a thin wall is hit, not passed) are cast along
// their motion; one that meets within the step gets the manifold built at
// the time of impact, carried back to the start of the step: its points'
// anchors are where the bodies meet, their gaps how far they have to close.
void World::castFastPairs(const StepContext& context) {
  castPairs_.clear();
  for (std::size_t k = 0; k < nearPairs_.size(); ++k) {
    const BodyPair& pair = pairs_[nearPairs_[k]];
    const PairAnswer& answer = pairAnswers_[k];
    pairAnswers_[k].cast = -1;
    if (answer.kept || answer.result.status != ContactStatus::Separated ||
        pairOutcomes_[nearPairs_[k]] == PairOutcome::Offloaded)
      continue;
    const double smallest = std::min(bodies_[pair.a].collider().localBounds().halfExtents().minCoeff(),
                                     bodies_[pair.b].collider().localBounds().halfExtents().minCoeff());
    if ((stepMotion(pair.b, context) - stepMotion(pair.a, context)).norm() > 0.5 * smallest) castPairs_.push_back(k);
  }
  castManifolds_.resize(castPairs_.size());
  const double tolerance = 0.1 * solver_->touchingGap();
  tasks_->parallelFor(castPairs_.size(), 1, [&](std::size_t begin, std::size_t end) {
    ManifoldScratch scratch;
    for (std::size_t j = begin; j < end; ++j) {
      PairAnswer& answer = pairAnswers_[castPairs_[j]];
      const BodyPair& pair = pairs_[nearPairs_[castPairs_[j]]];
      const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
      const std::optional<LinearCastHit> hit =
          linearCast(a.collider(), a.transform(), stepMotion(pair.a, context), b.collider(), b.transform(),
                     stepMotion(pair.b, context), tolerance, settings_.narrowPhase);
      if (!hit || hit->fraction == 0.0) continue;
      ContactManifold& manifold = castManifolds_[j];
      manifold = ContactManifold{};
      manifold.a = pair.a;
      manifold.b = pair.b;
      buildManifold(a.collider(), hit->a, b.collider(), hit->b, hit->result, answer.reach, scratch, manifold);
      for (int p = 0; p < manifold.pointCount; ++p) {
        ManifoldPoint& point = manifold.points[p];
        point.pointA = a.transform().apply(point.localA);
        point.pointB = b.transform().apply(point.localB);
        point.separation = (point.pointB - point.pointA).dot(manifold.normal);
      }
      answer.cast = static_cast<int>(j);
    }
  });
}

// One batch for the whole pass: a GPU pays per dispatch and readback, not per pair.
void World::testOffloadedPairs() {
  offloadRequests_.clear();
  offloadPairs_.clear();
  for (std::size_t k = 0; k < nearPairs_.size(); ++k) {
    if (pairOutcomes_[nearPairs_[k]] != PairOutcome::Offloaded) continue;
    const BodyPair& pair = pairs_[nearPairs_[k]];
    offloadRequests_.push_back({pair.a, pair.b, pairAnswers_[k].reach});
    offloadPairs_.push_back(k);
  }
  offloaded_.clear();
  if (offloadRequests_.empty()) return;
  offload_->collide(bodies_, offloadRequests_, offloaded_);
  for (std::size_t k = 0; k < offloadPairs_.size(); ++k) pairAnswers_[offloadPairs_[k]].result = offloaded_[k].result;
}

// In pair order: the counters, the candidates the solver turns into
// manifolds (all at once, so it can build them in parallel) and the touching
// contacts.
void World::gatherContacts(const StepContext& context) {
  const double touchingGap = solver_->touchingGap();
  candidates_.clear();
  reaches_.clear();
  manifoldSources_.clear();
  std::size_t offloadedSoFar = 0;
  for (std::size_t i = 0, k = 0; i < pairs_.size(); ++i) {
    const PairOutcome outcome = pairOutcomes_[i];
    if (outcome == PairOutcome::Skipped) continue;
    if (outcome == PairOutcome::BoundsRejected) {
      ++stats_.boundsRejected;
      continue;
    }
    const PairAnswer& test = pairAnswers_[k++];
    const Contact contact{pairs_[i].a, pairs_[i].b, test.result};
    if (test.kept)
      stats_.narrowPhase.addReused();
    else
      stats_.narrowPhase.add(contact.result);
    if (settings_.bruteForceBothOrders) stats_.narrowPhase.add(test.reversed);
    candidates_.push_back(contact);
    reaches_.push_back(test.reach);
    if (outcome == PairOutcome::Offloaded)
      manifoldSources_.push_back({&offloaded_[offloadedSoFar++].manifold, test.kept});
    else if (test.cast >= 0)
      manifoldSources_.push_back({&castManifolds_[static_cast<std::size_t>(test.cast)], nullptr});
    else
      manifoldSources_.push_back({nullptr, test.kept});
    if (contact.result.status == ContactStatus::Separated && contact.result.distance > touchingGap) continue;
    contacts_.push_back(contact);
  }
  stats_.manifoldPoints += solver_->addCandidates(candidates_, reaches_, bodies_, context, manifoldSources_);
}

// The answers worth taking again next pass: this pass's manifolds (in pair
// order, as the candidates) whose pair was tested anew with the box-box or
// GJK/EPA route, at today's poses; those taken again keep their old poses.
void World::keepAnswers() {
  if (!reusesContacts()) return;
  kept_.beginNext();
  std::size_t candidate = 0;
  for (const ContactManifold& manifold : solver_->manifolds()) {
    while (candidate < candidates_.size() &&
           (candidates_[candidate].a != manifold.a || candidates_[candidate].b != manifold.b))
      ++candidate;
    if (candidate == candidates_.size()) break;
    const ManifoldSource& source = manifoldSources_[candidate];
    if (source.kept) {
      kept_.carry({manifold.a, manifold.b});
      continue;
    }
    if (source.built || !worthReusing(candidates_[candidate].result)) continue;
    ReusableContact& entry = kept_.fresh({manifold.a, manifold.b});
    entry.a = bodies_[manifold.a].transform();
    entry.b = bodies_[manifold.b].transform();
    entry.result = candidates_[candidate].result;
    entry.manifold = manifold;
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = entry.manifold.points[p];
      point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = point.stepNormalImpulse = 0.0;
    }
  }
  kept_.endNext();
}

// The design's baseline without static-pair skipping: pairs of bodies that
// cannot move still cost an overlap test and, when their boxes overlap, a
// narrow-phase test whose answer nobody uses. Rows (the lower body of each
// pair) run in parallel; their counts are summed after, in row order.
void World::testStaticPairs() {
  staticRows_.assign(bodies_.size(), StaticRowCounts{});
  tasks_->parallelFor(bodies_.size(), staticRowGrain, [&](std::size_t begin, std::size_t end) {
    for (auto id = static_cast<BodyId>(begin); id < end; ++id) staticRows_[id] = testStaticRow(id);
  });
  for (const StaticRowCounts& row : staticRows_) {
    stats_.staticPairsTested += row.tested;
    stats_.narrowPhase.pairs += row.narrowPhase.pairs;
    stats_.narrowPhase.fastPath += row.narrowPhase.fastPath;
    stats_.narrowPhase.gjk += row.narrowPhase.gjk;
    stats_.narrowPhase.epa += row.narrowPhase.epa;
  }
}

World::StaticRowCounts World::testStaticRow(BodyId i) const {
  StaticRowCounts counts;
  if (!bodies_[i].isStatic() || !present_[i]) return counts;
  const Aabb boxI = bodies_[i].collider().worldBounds(bodies_[i].transform());
  for (BodyId j = i + 1; j < bodies_.size(); ++j) {
    if (!bodies_[j].isStatic() || !present_[j]) continue;
    ++counts.tested;
    if (!boxI.overlaps(bodies_[j].collider().worldBounds(bodies_[j].transform()))) continue;
    counts.narrowPhase.add(collide(bodies_[i].collider(), bodies_[i].transform(), bodies_[j].collider(),
                                   bodies_[j].transform(), settings_.narrowPhase));
  }
  return counts;
}

// A sleeping body touched by an awake one wakes before the response, so the
// response sees it as the dynamic body it is: touching now (the narrow
// phase's contacts), or reached within this step by a speculative contact
// (closesOnSleeper). Left asleep, it would be a wall for the step: a ball
// rolling into a sleeper bounced back off it instead of passing it its
// momentum.
bool World::wakeTouchedBodies(const StepContext& context) {
  bool woke = false;
  const auto wakeIfTouched = [&](BodyId sleeper, BodyId other, bool touches) {
    if (!asleep_[sleeper] || !isMoving(other) || !touches) return;
    wake(sleeper);
    woke = true;
  };
  for (const Contact& contact : contacts_) {
    wakeIfTouched(contact.a, contact.b, true);
    wakeIfTouched(contact.b, contact.a, true);
  }
  for (const ContactManifold& manifold : solver_->manifolds()) {
    if (asleep_[manifold.a] == asleep_[manifold.b]) continue;
    const BodyId sleeper = asleep_[manifold.a] ? manifold.a : manifold.b;
    const BodyId other = sleeper == manifold.a ? manifold.b : manifold.a;
    if (asleep_[sleeper] && isMoving(other)) wakeIfTouched(sleeper, other, closesOnSleeper(manifold, other, context));
  }
  return woke;
}

// Whether the moving body of a manifold with a sleeper can close any of its
// points' gaps this step: its speed at the point towards the sleeper, plus
// what its forces add in the step, over the step, reaches the gap.
bool World::closesOnSleeper(const ContactManifold& manifold, BodyId mover, const StepContext& context) const {
  const RigidBody& body = bodies_[mover];
  // The normal points from a to b; towards the sleeper is -normal for b.
  const Vec3 towards = mover == manifold.a ? manifold.normal : Vec3(-manifold.normal);
  const double gain = body.stepAcceleration().norm() * context.dt;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    const Vec3 at = mover == manifold.a ? point.pointA : point.pointB;
    const Vec3 velocity = body.linearVelocity() + body.angularVelocity().cross(at - body.position());
    const double closing = std::max(0.0, velocity.dot(towards)) + gain;
    if (closing * context.dt >= point.separation - solver_->touchingGap()) return true;
  }
  return false;
}

void World::solveContacts(const StepContext& context) {
  SolverStepReport report;
  {
    const StageTimer timer(stats_.profile.solver);
    report = solver_->solve(bodies_, refreshMoving(), contacts_, context);
  }
  stats_.profile.solverIslands = report.islandSeconds;
  stats_.responses = report.responses;
  stats_.largestPenetration = report.largestPenetration;
  stats_.substeps = report.substeps;
  stats_.contactHertz = report.contactHertz;
}

// Islands: awake bodies joined by this step's touching contacts. Static,
// sleeping and frozen bodies do not link, so piles resting on one floor stay
// apart. Each body is labelled with its island's lowest id; a sleeping body
// keeps the label it fell asleep with, which is what wake() follows.
// Bodies are numbered by their rank among the movable ones (ascending, so a
// set's root, its lowest rank, is its lowest id).
void World::linkIslands() {
  const std::vector<BodyId>& ids = movable_.ids;
  islandRank_.resize(bodies_.size());
  for (std::size_t k = 0; k < ids.size(); ++k) islandRank_[ids[k]] = static_cast<BodyId>(k);
  DisjointSets sets(ids.size());
  for (const Contact& contact : contacts_)
    if (movable_[contact.a] && movable_[contact.b]) sets.unite(islandRank_[contact.a], islandRank_[contact.b]);
  for (std::size_t k = 0; k < ids.size(); ++k) island_[ids[k]] = ids[sets.find(static_cast<std::uint32_t>(k))];
}

void World::updateSlowTimes(const StepContext& context) {
  for (const BodyId id : movable_.ids) {
    const RigidBody& body = bodies_[id];
    const bool slow = body.linearVelocity().norm() < settings_.sleepLinearSpeed &&
                      body.angularVelocity().norm() < settings_.sleepAngularSpeed;
    slowTime_[id] = slow ? slowTime_[id] + context.dt : 0.0;
  }
}

// An island sleeps as a whole once its most recently moving body has been
// slow for timeToSleep. Deciding per island, not per contact, keeps the
// answer independent of contact order: a body never sleeps while anything it
// is linked to, however indirectly, still moves.
bool World::updateSleep(const StepContext& context) {
  updateSlowTimes(context);
  if (!settings_.allowSleep) return false;
  const std::vector<BodyId>& ids = movable_.ids;
  std::vector<double> islandSlowTime(ids.size(), std::numeric_limits<double>::infinity());  // by the root's rank
  std::vector<std::uint32_t> islandSize(ids.size(), 0);
  for (const BodyId id : ids) {
    double& slowest = islandSlowTime[islandRank_[island_[id]]];
    slowest = std::min(slowest, slowTime_[id]);
    ++islandSize[islandRank_[island_[id]]];
  }
  bool fellAsleep = false;
  for (const BodyId id : ids) {
    const BodyId root = islandRank_[island_[id]];
    if (islandSlowTime[root] < settings_.timeToSleep) continue;
    putToSleep(id, islandSize[root] == 1);
    fellAsleep = true;
  }
  return fellAsleep;
}

void World::removeBody(BodyId id) {
  if (id >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(id));
  if (!present_[id]) return;
  setAsleep(id, false);
  present_[id] = false;
  slowTime_[id] = 0.0;
  island_[id] = id;
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
  if (id >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(id));
  if (present_[id]) return;
  present_[id] = true;
  if (frozen_[id]) return;  // a non-finite body stays out of the broad phase
  updateActivity(id);
  const RigidBody& body = bodies_[id];
  proxies_[id] = broadPhase_->addProxy(body.collider().worldBounds(body.transform()), id,
                                       body.isStatic() ? ProxyMotion::Static : ProxyMotion::Dynamic);
}

void World::scheduleLifetime(const BodyLifetime& lifetime) {
  const BodyId id = lifetime.body;
  if (id >= bodies_.size()) throw std::invalid_argument("no body " + std::to_string(id));
  for (const BodyLifetime& scheduled : lifetimes_)
    if (scheduled.body == id) throw std::invalid_argument("body " + std::to_string(id) + " already has a lifetime");
  if (lifetime.addAtStep < 0) throw std::invalid_argument("add step must not be negative");
  if (lifetime.removeAtStep && *lifetime.removeAtStep <= lifetime.addAtStep)
    throw std::invalid_argument("remove step must come after the add step");
  if (lifetime.addAtStep < stepCount_ && lifetime.addAtStep > 0)
    throw std::invalid_argument("add step " + std::to_string(lifetime.addAtStep) + " has passed");
  if (lifetime.removeAtStep && *lifetime.removeAtStep <= stepCount_)
    throw std::invalid_argument("remove step " + std::to_string(*lifetime.removeAtStep) + " has passed");
  lifetimes_.push_back(lifetime);
  if (lifetime.addAtStep > stepCount_) removeBody(id);
}

// Removals first, in the order scheduled, so a body leaving and one arriving
// on the same step never meet.
void World::applyLifetimes(int state) {
  for (const BodyLifetime& lifetime : lifetimes_)
    if (lifetime.removeAtStep == state) removeBody(lifetime.body);
  for (const BodyLifetime& lifetime : lifetimes_)
    if (lifetime.addAtStep == state) restoreBody(lifetime.body);
}

// A non-finite body is reported with the step it happened on, then frozen and
// taken out of the broad phase: it cannot poison the tree or other bodies.
void World::freezeNonFiniteBodies() {
  std::vector<BodyId> checked = activeBodies();
  if (!edited_.empty()) {
    checked.insert(checked.end(), edited_.begin(), edited_.end());
    std::sort(checked.begin(), checked.end());
    checked.erase(std::unique(checked.begin(), checked.end()), checked.end());
    for (const BodyId id : edited_) isEdited_[id] = 0;
    edited_.clear();
  }
  for (const BodyId id : checked) {
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
