#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "engine/broadphase/brute_force_broad_phase.h"
#include "engine/broadphase/tree_broad_phase.h"
#include "engine/disjoint_sets.h"
#include "engine/narrowphase/narrow_phase.h"

namespace physdbg {
namespace {

std::unique_ptr<BroadPhase> makeBroadPhase(const WorldSettings& settings) {
  if (settings.broadPhase == BroadPhaseKind::BruteForce) {
    BruteForceOptions options;
    options.margin = settings.fatMargin;
    options.checkBothOrders = settings.bruteForceBothOrders;
    return std::make_unique<BruteForceBroadPhase>(options);
  }
  DynamicAabbTreeOptions options;
  options.margin = settings.fatMargin;
  return std::make_unique<TreeBroadPhase>(options);
}

}  // namespace

World::World(const WorldSettings& settings) : settings_(settings), broadPhase_(makeBroadPhase(settings)) {
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt)) throw std::invalid_argument("dt must be positive");
  if (!isFinite(settings.gravity)) throw std::invalid_argument("gravity must be finite");
  if (!(settings.fatMargin >= 0.0)) throw std::invalid_argument("fat margin must not be negative");
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
  frozen_.push_back(false);
  asleep_.push_back(false);
  slowTime_.push_back(0.0);
  island_.push_back(id);
  return id;
}

const DynamicAabbTree* World::tree() const {
  const auto* tree = dynamic_cast<const TreeBroadPhase*>(broadPhase_.get());
  return tree ? &tree->tree() : nullptr;
}

// The order of a step, as the design describes it. The seed solver follows
// it literally; the sequential-impulse solver integrates velocities and
// positions itself, in substeps around its contact solve.
void World::step() {
  stats_ = StepStats{};
  const bool seed = settings_.solver.kind == SolverKind::Seed;
  applyForces();  // gravity, user forces and impulses
  if (seed) integrateVelocities();
  freezeNonFiniteBodies();
  updateBroadPhase();  // fat boxes follow the bodies that moved
  findContacts();      // candidate pairs, then the narrow phase on each
  // A body woken by a touch had no pairs with what else it rests on (asleep,
  // its proxy made none): find them before solving, or it would fall a step.
  while (wakeTouchedBodies()) findContacts();
  if (seed) {
    resolveContacts();  // every response after every test is done
    integratePositions();
  } else {
    solveContacts();  // substeps: velocities, contacts, positions
  }
  events_.update(eventContacts(), dormantPairs(), listener_);
  if (keepHistory_) history_.add(stepTouchedPoints());
  linkIslands();
  keepRestingContacts(updateSleep());
  freezeNonFiniteBodies();
  ++stepCount_;
}

// An island fell asleep together, so it wakes together: a body left asleep
// beside a woken neighbour would hold no contacts with it (sleeping proxies
// make no pairs) until the next touch woke it a step late.
void World::wake(BodyId id) {
  if (!asleep_.at(id)) return;
  const BodyId island = island_[id];
  for (BodyId member = 0; member < bodies_.size(); ++member)
    if (asleep_[member] && island_[member] == island) wakeBody(member);
}

void World::wakeBody(BodyId id) {
  asleep_[id] = false;
  slowTime_[id] = 0.0;
  if (proxies_[id] >= 0) broadPhase_->setProxyActive(proxies_[id], true);
}

void World::putToSleep(BodyId id) {
  asleep_[id] = true;
  bodies_[id].setLinearVelocity(Vec3::Zero());
  bodies_[id].setAngularVelocity(Vec3::Zero());
  broadPhase_->setProxyActive(proxies_[id], false);
}

// Wakes come first: a pushed body wakes its whole island, bodies before it
// in id order included, and each of them must then begin the step awake.
void World::applyForces() {
  wakePushedBodies();
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    RigidBody& body = bodies_[id];
    if (frozen_[id] || body.isStatic()) continue;
    if (asleep_[id]) {
      ++stats_.sleepingBodies;
      continue;
    }
    body.beginStep(settings_.gravity);
    ++stats_.awakeBodies;
    if (body.hasLocks()) ++stats_.lockedBodies;
  }
}

// A sleeping body that was pushed or given a velocity wakes up.
void World::wakePushedBodies() {
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    const RigidBody& body = bodies_[id];
    if (!asleep_[id] || frozen_[id]) continue;
    if (body.hasPendingForces() || body.linearVelocity() != Vec3::Zero() || body.angularVelocity() != Vec3::Zero())
      wake(id);
  }
}

void World::integrateVelocities() {
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (isMoving(id)) bodies_[id].integrateVelocity(settings_.dt);
  }
}

// With sequential impulses the box covers the whole step's sweep, so a fast
// body finds what lies ahead and gets speculative contacts before it arrives.
void World::updateBroadPhase() {
  const bool sweep = settings_.solver.kind == SolverKind::SequentialImpulse;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (!isMoving(id)) continue;
    const RigidBody& body = bodies_[id];
    const Vec3 displacement = (body.linearVelocity() + body.stepAcceleration() * settings_.dt) * settings_.dt;
    Aabb box = body.collider().worldBounds(body.transform());
    if (sweep) box = box.merged({box.min + displacement, box.max + displacement});
    broadPhase_->moveProxy(proxies_[id], box, displacement);
  }
}

void World::findContacts() {
  broadPhase_->findPairs(pairs_);
  stats_.broadPhase = broadPhase_->stats();
  stats_.candidatePairs = static_cast<int>(pairs_.size());
  contacts_.clear();
  std::swap(previousManifolds_, manifolds_);
  manifolds_.clear();
  const bool speculative = settings_.solver.kind == SolverKind::SequentialImpulse;
  for (const BodyPair& pair : pairs_) {
    const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
    // Fat boxes overlap long before the shapes can touch: when even the tight
    // boxes, grown by how far the pair can close this step, stay apart, the
    // narrow phase has nothing to say.
    const double reach = speculative ? speculativeDistance(pair) : settings_.narrowPhase.touchingTolerance;
    if (!a.collider().worldBounds(a.transform()).enlarged(reach).overlaps(b.collider().worldBounds(b.transform()))) {
      ++stats_.boundsRejected;
      continue;
    }
    const ContactResult result =
        collide(a.collider(), a.transform(), b.collider(), b.transform(), settings_.narrowPhase);
    stats_.narrowPhase.add(result);
    if (speculative && (result.status != ContactStatus::Separated || result.distance <= reach))
      addManifold(pair, result, reach);
    // The solver holds resting bodies a hair apart (a speculative point aims
    // at zero gap), so with it "touching" means within the linear slop.
    const double touchingGap = speculative ? settings_.solver.linearSlop : 0.0;
    if (result.status == ContactStatus::Separated && result.distance > touchingGap) continue;
    contacts_.push_back({pair.a, pair.b, result});
  }
  stats_.manifolds = static_cast<int>(manifolds_.size());
  if (!settings_.skipStaticPairs) testStaticPairs();
  stats_.contacts = static_cast<int>(contacts_.size());
}

// How far apart two surfaces may be and still get a (speculative) contact:
// the most they can close in one step, plus a few slops so resting contacts
// are found before they touch.
double World::speculativeDistance(const BodyPair& pair) const {
  const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
  const double reachA = a.collider().localBounds().halfExtents().norm();
  const double reachB = b.collider().localBounds().halfExtents().norm();
  const double closingSpeed = (b.linearVelocity() - a.linearVelocity()).norm() +
                              (a.stepAcceleration().norm() + b.stepAcceleration().norm()) * settings_.dt +
                              a.angularVelocity().norm() * reachA + b.angularVelocity().norm() * reachB;
  return 4.0 * settings_.solver.linearSlop + closingSpeed * settings_.dt;
}

void World::addManifold(const BodyPair& pair, const ContactResult& result, double reach) {
  const RigidBody &a = bodies_[pair.a], &b = bodies_[pair.b];
  ContactManifold& manifold = manifolds_.emplace_back();
  manifold.a = pair.a;
  manifold.b = pair.b;
  buildManifold(a.collider(), a.transform(), b.collider(), b.transform(), result, reach, manifoldScratch_, manifold);
  stats_.manifoldPoints += manifold.pointCount;
}

// The design's baseline without static-pair skipping: pairs of bodies that
// cannot move still cost an overlap test and, when their boxes overlap, a
// narrow-phase test whose answer nobody uses.
void World::testStaticPairs() {
  for (BodyId i = 0; i < bodies_.size(); ++i) {
    if (!bodies_[i].isStatic()) continue;
    const Aabb boxI = bodies_[i].collider().worldBounds(bodies_[i].transform());
    for (BodyId j = i + 1; j < bodies_.size(); ++j) {
      if (!bodies_[j].isStatic()) continue;
      ++stats_.staticPairsTested;
      if (!boxI.overlaps(bodies_[j].collider().worldBounds(bodies_[j].transform()))) continue;
      stats_.narrowPhase.add(collide(bodies_[i].collider(), bodies_[i].transform(), bodies_[j].collider(),
                                     bodies_[j].transform(), settings_.narrowPhase));
    }
  }
}

// A sleeping body touched by an awake one wakes before the response, so the
// response sees it as the dynamic body it is.
bool World::wakeTouchedBodies() {
  bool woke = false;
  for (const Contact& contact : contacts_) {
    if (asleep_[contact.a] && isMoving(contact.b)) {
      wake(contact.a);
      woke = true;
    }
    if (asleep_[contact.b] && isMoving(contact.a)) {
      wake(contact.b);
      woke = true;
    }
  }
  return woke;
}

void World::resolveContacts() {
  for (const Contact& contact : contacts_) {
    if (frozen_[contact.a] || frozen_[contact.b]) continue;
    if (respondToContact(bodies_[contact.a], bodies_[contact.b], contact.result, settings_.response))
      ++stats_.responses;
  }
}

void World::solveContacts() {
  movable_.resize(bodies_.size());
  for (BodyId id = 0; id < bodies_.size(); ++id) movable_[id] = isMoving(id);
  if (settings_.solver.warmStarting) warmStartFromPreviousStep();
  const SolverStepReport report =
      solver_.step(bodies_, movable_, manifolds_, settings_.dt, settings_.solver, settings_.gravity);
  stats_.largestPenetration = report.largestPenetration;
  stats_.substeps = report.substeps;
  stats_.contactHertz = report.contactHertz;
  stats_.responses = static_cast<int>(manifolds_.size());
}

// Impulses of points that persist (same pair, same feature id) carry over.
void World::warmStartFromPreviousStep() {
  std::size_t previous = 0;
  for (ContactManifold& manifold : manifolds_) {
    const BodyPair pair{manifold.a, manifold.b};
    while (previous < previousManifolds_.size() &&
           BodyPair{previousManifolds_[previous].a, previousManifolds_[previous].b} < pair)
      ++previous;
    if (previous == previousManifolds_.size()) break;
    const ContactManifold& old = previousManifolds_[previous];
    if (BodyPair{old.a, old.b} != pair) continue;
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      for (int q = 0; q < old.pointCount; ++q) {
        if (old.points[q].featureId != point.featureId) continue;
        point.normalImpulse = old.points[q].normalImpulse;
        point.tangentImpulse[0] = old.points[q].tangentImpulse[0];
        point.tangentImpulse[1] = old.points[q].tangentImpulse[1];
        break;
      }
    }
  }
}

// Pairs that were touching and whose bodies are now all asleep (or static):
// they still touch, silently.
std::vector<BodyPair> World::dormantPairs() const {
  std::vector<BodyPair> dormant;
  for (const BodyPair& pair : events_.touchingPairs()) {
    if (frozen_[pair.a] || frozen_[pair.b] || isMoving(pair.a) || isMoving(pair.b)) continue;
    if (asleep_[pair.a] || asleep_[pair.b]) dormant.push_back(pair);
  }
  return dormant;
}

namespace {

// A speculative manifold the solver pushed on: the bodies were about to meet
// and were stopped before they did. Reported at its hardest-pushed point.
std::optional<Contact> speculativeImpact(const ContactManifold& manifold) {
  const ManifoldPoint* strongest = nullptr;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    if (point.normalImpulse > 0.0 && (!strongest || point.normalImpulse > strongest->normalImpulse))
      strongest = &point;
  }
  if (!strongest) return std::nullopt;
  ContactResult result;
  result.status = strongest->separation > 0.0 ? ContactStatus::Separated : ContactStatus::Touching;
  result.distance = std::max(0.0, strongest->separation);
  result.normal = manifold.normal;
  result.pointA = strongest->pointA;
  result.pointB = strongest->pointB;
  return Contact{manifold.a, manifold.b, result};
}

}  // namespace

// The touching pairs contact events report: the narrow phase's, and under
// sequential impulses also each pair whose speculative points the solver
// pushed on (an impact stopped just before the surfaces met is an impact).
// Both lists are in pair order, and so is the result.
const std::vector<Contact>& World::eventContacts() {
  if (settings_.solver.kind != SolverKind::SequentialImpulse) return contacts_;
  eventContacts_.clear();
  std::size_t next = 0;
  const auto pairOf = [this](std::size_t index) { return BodyPair{contacts_[index].a, contacts_[index].b}; };
  for (const ContactManifold& manifold : manifolds_) {
    const BodyPair pair{manifold.a, manifold.b};
    while (next < contacts_.size() && pairOf(next) < pair) eventContacts_.push_back(contacts_[next++]);
    if (next < contacts_.size() && pairOf(next) == pair) continue;
    if (const std::optional<Contact> impact = speculativeImpact(manifold)) eventContacts_.push_back(*impact);
  }
  eventContacts_.insert(eventContacts_.end(), contacts_.begin() + static_cast<std::ptrdiff_t>(next), contacts_.end());
  return eventContacts_;
}

void World::integratePositions() {
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (isMoving(id)) bodies_[id].integratePosition(settings_.dt);
  }
}

// Islands: awake bodies joined by this step's touching contacts. Static,
// sleeping and frozen bodies do not link, so piles resting on one floor stay
// apart. Each body is labelled with its island's lowest id; a sleeping body
// keeps the label it fell asleep with, which is what wake() follows.
void World::linkIslands() {
  DisjointSets sets(bodies_.size());
  for (const Contact& contact : contacts_)
    if (isMoving(contact.a) && isMoving(contact.b)) sets.unite(contact.a, contact.b);
  for (BodyId id = 0; id < bodies_.size(); ++id)
    if (isMoving(id)) island_[id] = sets.find(id);
}

void World::updateSlowTimes() {
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (!isMoving(id)) continue;
    const RigidBody& body = bodies_[id];
    const bool slow = body.linearVelocity().norm() < settings_.sleepLinearSpeed &&
                      body.angularVelocity().norm() < settings_.sleepAngularSpeed;
    slowTime_[id] = slow ? slowTime_[id] + settings_.dt : 0.0;
  }
}

// An island sleeps as a whole once its most recently moving body has been
// slow for timeToSleep. Deciding per island, not per contact, keeps the
// answer independent of contact order: a body never sleeps while anything it
// is linked to, however indirectly, still moves.
bool World::updateSleep() {
  updateSlowTimes();
  if (!settings_.allowSleep) return false;
  std::vector<double> islandSlowTime(bodies_.size(), std::numeric_limits<double>::infinity());
  for (BodyId id = 0; id < bodies_.size(); ++id)
    if (isMoving(id)) islandSlowTime[island_[id]] = std::min(islandSlowTime[island_[id]], slowTime_[id]);
  bool fellAsleep = false;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (!isMoving(id) || islandSlowTime[island_[id]] < settings_.timeToSleep) continue;
    putToSleep(id);
    fellAsleep = true;
  }
  return fellAsleep;
}

// A non-finite body is reported with the step it happened on, then frozen and
// taken out of the broad phase: it cannot poison the tree or other bodies.
void World::freezeNonFiniteBodies() {
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (frozen_[id] || bodies_[id].hasFiniteState()) continue;
    frozen_[id] = true;
    if (proxies_[id] >= 0) broadPhase_->removeProxy(proxies_[id]);
    proxies_[id] = -1;
    faults_.push_back({id, stepCount_ + 1, "position, orientation or velocity became NaN or Inf"});
  }
}

}  // namespace physdbg
