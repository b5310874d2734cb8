#include "engine/solver/sequential_impulse_solver.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "engine/contacts/material_combine.h"
#include "engine/parallel/task_system.h"
#include "engine/solver/bounce.h"
#include "engine/solver/constraint_colouring.h"
#include "engine/solver/resting_load.h"
#include "engine/stage_timer.h"

namespace physdbg {
namespace {

// Where batchIslands closes a batch: enough manifolds that a thread's share
// outweighs handing it over, few enough that a thousand boxes make several.
constexpr std::size_t batchManifolds = 128;
// Fewer manifolds than this in the batches that may run side by side run on
// the stepping thread.
constexpr std::size_t batchSplitMinimum = 2 * batchManifolds;

bool touchesKinematic(const RankedTable<BodyTraits>& traits, const std::vector<ContactManifold>& manifolds,
                      const ContactIsland& island) {
  for (std::uint32_t m : island.manifolds)
    if (traits[manifolds[m].a].kinematic || traits[manifolds[m].b].kinematic) return true;
  return false;
}

// A fixed tangent basis from the normal alone, so tangent impulses stay
// meaningful for warm starting from one step to the next.
void tangentBasis(const Vec3& normal, Vec3& first, Vec3& second) {
  const Vec3 axis = std::abs(normal.x()) < 0.57735 ? Vec3::UnitX() : Vec3::UnitY();
  first = normal.cross(axis).normalized();
  second = normal.cross(first);
}

// Share of the largest magnitude involved that an approach case's test lets
// a value fall below zero: far above the few ulps a 4x4 product rounds by,
// far below any impulse that matters.
constexpr double kApproachRounding = 1e-9;

GapTurn gapTurnOf(ColliderKind kind) {
  switch (kind) {
    case ColliderKind::Sphere: return GapTurn::None;
    case ColliderKind::Capsule: return GapTurn::Swing;  // symmetric about its local y axis
    default: return GapTurn::Whole;
  }
}

// The body's rotation for measuring gaps (GapTurn): its turn since the step
// began, less the part its shape does not show. A capsule's turn q splits
// into a twist about its axis and the swing that moves the axis (q = swing
// twist); only the swing moves its surface.
Mat3 gapRotation(const SolverBody& body) {
  switch (body.gapTurn) {
    case GapTurn::None: return body.rotation;
    case GapTurn::Whole: return body.motion.orientation.toRotationMatrix();
    case GapTurn::Swing: break;
  }
  const Quat turn = body.motion.orientation * body.startOrientation.conjugate();
  const Vec3 axis = body.startOrientation * body.symmetryAxis;
  const Vec3 along = turn.vec().dot(axis) * axis;
  Quat twist(turn.w(), along.x(), along.y(), along.z());
  if (twist.squaredNorm() == 0.0) return body.motion.orientation.toRotationMatrix();  // a half turn about a crossing axis
  twist.normalize();
  return ((turn * twist.conjugate()) * body.startOrientation).normalized().toRotationMatrix();
}

// The largest magnitude among a manifold's `count` points.
double largestOf(const Eigen::Vector4d& values, int count) {
  double result = 0.0;
  for (int p = 0; p < count; ++p) result = std::max(result, std::abs(values[p]));
  return result;
}

// Solves the case where the points in `mask` push and stop exactly and the
// others give their impulse back: M_SS change_S = -(target_S + M_S,rest
// change_rest). False when it does not hold.
bool tryApproachCase(const Eigen::Matrix4d& mass, const Eigen::Vector4d& target, const Eigen::Vector4d& impulse,
                     int count, int mask, Eigen::Vector4d& change) {
  const auto inside = [mask](int p) { return ((mask >> p) & 1) != 0; };
  Eigen::Vector4d trial = Eigen::Vector4d::Zero();
  for (int p = 0; p < count; ++p)
    if (!inside(p)) trial[p] = -impulse[p];
  // The subset's block, with 1 on the diagonal elsewhere (and 0 on the
  // right), so one fixed-size factorisation serves every subset.
  Eigen::Matrix4d block = Eigen::Matrix4d::Identity();
  Eigen::Vector4d right = Eigen::Vector4d::Zero();
  for (int i = 0; i < count; ++i) {
    if (!inside(i)) continue;
    right[i] = -(target[i] + mass.row(i).dot(trial));
    for (int j = 0; j < count; ++j)
      if (inside(j)) block(i, j) = mass(i, j);
  }
  const Eigen::Vector4d solved = block.ldlt().solve(right);
  for (int p = 0; p < count; ++p)
    if (inside(p)) trial[p] = solved[p];
  const Eigen::Vector4d total = impulse + trial, velocity = target + mass * trial;
  const double scale = std::max({largestOf(target, count), largestOf(impulse, count), largestOf(trial, count)});
  const double allowed = kApproachRounding * scale;
  for (int p = 0; p < count; ++p) {
    // A singular block may leave its points moving: not this case.
    if (inside(p) ? (total[p] < -allowed || std::abs(velocity[p]) > allowed) : velocity[p] < -allowed) return false;
  }
  change = trial;
  return true;
}

// The other cases of the approach solve, when neither every point nor none
// pushes (a box a micro-radian off face on: a corner or two may arrive
// first). First the points the all-pushing answer left pushing (`allPush`,
// usually right), then every proper subset, the largest first and in mask
// order: points outside give their impulse back, points inside stop
// exactly, and the first case whose impulses stay pushing and whose other
// points stay opening (up to rounding, as above) is the answer. Three or
// fewer points of a face give a regular block, solved by LDLT.
bool solveMixedApproach(const Eigen::Matrix4d& mass, const Eigen::Vector4d& target, const Eigen::Vector4d& impulse,
                        const Eigen::Vector4d& allPush, int count, Eigen::Vector4d& change) {
  const int full = (1 << count) - 1;
  int guess = 0;
  for (int p = 0; p < count; ++p)
    if (impulse[p] + allPush[p] > 0.0) guess |= 1 << p;
  if (guess != 0 && guess != full && tryApproachCase(mass, target, impulse, count, guess, change)) return true;
  for (int size = count - 1; size >= 1; --size) {
    for (int mask = 1; mask < full; ++mask) {
      if (mask == guess || std::popcount(static_cast<unsigned>(mask)) != size) continue;
      if (tryApproachCase(mass, target, impulse, count, mask, change)) return true;
    }
  }
  return false;
}

}  // namespace

void SequentialImpulseSolver::manifoldGaps(const ContactManifold& manifold,
                                           double (&gaps)[ContactManifold::maxPoints]) const {
  const SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  pointGaps(manifold, a.motion.position, a.rotation, b.motion.position, b.rotation, gaps);
}

inline double SequentialImpulseSolver::rowVelocity(const ContactManifold& manifold, const PointConstraint& c,
                                                   const Vec3& direction, int row) const {
  const SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  return (b.motion.linearVelocity - a.motion.linearVelocity).dot(direction) +
         b.motion.angularVelocity.dot(c.crossB[row]) - a.motion.angularVelocity.dot(c.crossA[row]);
}

inline void SequentialImpulseSolver::applyRow(const ContactManifold& manifold, const PointConstraint& c,
                                              const Vec3& direction, int row, double impulse) {
  // An immovable body takes nothing, and is not written: other threads may read it.
  SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  if (a.movable) {
    a.motion.linearVelocity -= (c.inverseMassA * impulse) * direction.cwiseProduct(a.linearMask);
    a.motion.angularVelocity -= impulse * c.turnA[row];
  }
  if (b.movable) {
    b.motion.linearVelocity += (c.inverseMassB * impulse) * direction.cwiseProduct(b.linearMask);
    b.motion.angularVelocity += impulse * c.turnB[row];
  }
}

// The normal row of a point, also added to the step's total there (what the
// debugger shows as the contact's force): every normal impulse goes through
// here, so the total is exactly what the bodies received.
inline void SequentialImpulseSolver::applyNormal(const ContactManifold& manifold, const PointConstraint& c,
                                                 ManifoldPoint& point, double impulse) {
  applyRow(manifold, c, manifold.normal, 0, impulse);
  point.stepNormalImpulse += impulse;
}

// The box covers the whole step's sweep, so a fast body finds what lies
// ahead and gets speculative contacts before it arrives. It grows by the
// body's share of any contact reach (below) in every direction, not just
// along its displacement, so a pair the narrow phase may keep is found by any
// broad phase, whatever its margins: the contacts, and with them which
// islands are calm (calmSubsteps), do not depend on the broad phase. Spin is
// left to the broad phase's margin (0.1 m by default, about 6 m/s at the rim
// at 60 Hz): a long rod spinning fast would otherwise pair with everything.
PredictedMotion SequentialImpulseSolver::predictMotion(const RigidBody& body, const StepContext& step) const {
  const Vec3 displacement = (body.linearVelocity() + body.stepAcceleration() * step.dt) * step.dt;
  const BodyReach reach = bodyReach(body, step);
  // At least each body's part of contactReach (reachShare, spin included):
  // a pair the screen would call near must have overlapping boxes in the
  // tree, or a brute-force broad phase finds a speculative pair the tree
  // misses (two spinning balls, 2 mm apart).
  const double share = 4.0 * settings_.linearSlop +
                       (reach.linearVelocity.norm() + reach.acceleration * step.dt + reach.spin) * step.dt;
  const Aabb box = body.collider().worldBounds(body.transform());
  // A body whose motion turned non-finite is reported and frozen after the
  // step; its box stays where it is.
  if (!std::isfinite(share)) return {box, displacement};
  return {box.enlarged(share), displacement};
}

// How far apart two surfaces may be and still get a (speculative) contact:
// the most they can close in one step, plus a few slops so resting contacts
// are found before they touch.
// A sphere's surface stays where it is however it turns: its spin reaches
// nothing.
BodyReach SequentialImpulseSolver::bodyReach(const RigidBody& body, const StepContext&) const {
  const bool round = body.collider().kind() == ColliderKind::Sphere;
  const double radius = round ? 0.0 : body.collider().localBounds().halfExtents().norm();
  return {body.linearVelocity(), body.stepAcceleration().norm(), body.angularVelocity().norm() * radius};
}

double SequentialImpulseSolver::contactReach(const BodyReach& a, const BodyReach& b, const StepContext& step) const {
  const double closingSpeed =
      (b.linearVelocity - a.linearVelocity).norm() + (a.acceleration + b.acceleration) * step.dt + a.spin + b.spin;
  return 4.0 * settings_.linearSlop + closingSpeed * step.dt;
}

// Half the slops, and this body's own speed in place of the pair's closing
// speed: |v_b - v_a| <= |v_a| + |v_b| covers the rest.
double SequentialImpulseSolver::reachShare(const BodyReach& body, const StepContext& step) const {
  return 2.0 * settings_.linearSlop + (body.linearVelocity.norm() + body.acceleration * step.dt + body.spin) * step.dt;
}

void SequentialImpulseSolver::beginStep(std::vector<RigidBody>&, const MovableBodies&, const StepContext&) {
  previousImpulses_.remember(manifolds_);
  retireManifolds();
}

void SequentialImpulseSolver::clearContacts() { retireManifolds(); }

void SequentialImpulseSolver::retireManifolds() {
  if (manifolds_.size() > spareManifolds_.size()) std::swap(manifolds_, spareManifolds_);
  manifolds_.clear();
}

int SequentialImpulseSolver::addCandidate(const Contact& contact, const RigidBody& a, const RigidBody& b,
                                          double reach) {
  const ContactResult& result = contact.result;
  if (result.status == ContactStatus::Separated && result.distance > reach) return 0;
  ContactManifold& manifold = manifolds_.emplace_back();
  manifold.a = contact.a;
  manifold.b = contact.b;
  buildManifold(a.collider(), a.transform(), b.collider(), b.transform(), result, reach, manifoldScratch_, manifold);
  return manifold.pointCount;
}

SolverStepReport SequentialImpulseSolver::solve(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                                const std::vector<Contact>&, const StepContext& step) {
  if (settings_.warmStarting) warmStartFromPreviousStep(step);
  SolverStepReport report = solveManifolds(bodies, movable, manifolds_, step);
  report.responses = static_cast<int>(manifolds_.size());
  return report;
}

namespace {

// The overlap a resting load may add to a contact between bodies of this
// size (the smaller movable one's): restingOverlap, or a share of the size
// for bodies smaller than restingOverlap / relativeRestingOverlap.
double allowedOverlap(const SolverSettings& settings, double size) {
  return std::min(settings.restingOverlap, settings.relativeRestingOverlap * size);
}

}  // namespace

// The last step's impulses, matched by pair and point (warm_start_memory.h).
void SequentialImpulseSolver::warmStartFromPreviousStep(const StepContext& step) {
  previousImpulses_.carryInto(manifolds_, settings_.linearSlop, step.tasks);
}

namespace {

// A speculative manifold the solver pushed on at any time in the step: the
// bodies were about to meet and were stopped before they did. An impact that
// leaves no load (bodies moving on together) pushes in its first substeps
// only, so the step's total decides, not the last substep's impulse.
// Reported at its hardest-pushed point.
std::optional<Contact> speculativeImpact(const ContactManifold& manifold, const RankedTable<SolverBody>& bodies) {
  const ManifoldPoint* strongest = nullptr;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    if (point.stepNormalImpulse > 0.0 && (!strongest || point.stepNormalImpulse > strongest->stepNormalImpulse))
      strongest = &point;
  }
  if (!strongest) return std::nullopt;
  ContactResult result;
  result.status = strongest->separation > 0.0 ? ContactStatus::Separated : ContactStatus::Touching;
  result.distance = std::max(0.0, strongest->separation);
  result.normal = manifold.normal;
  // Where the bodies met: a's anchor where the step left a (the impact
  // closed the gap there), for both; the points of the step's start lie
  // up to a step's travel away (16 cm for a ball landing at 10 m/s).
  const BodyMotion& a = bodies[manifold.a].motion;
  result.pointA = a.position + a.orientation * strongest->localA;
  result.pointB = result.pointA;
  return Contact{manifold.a, manifold.b, result};
}

}  // namespace

// The narrow phase's touching pairs, and also each pair whose speculative
// points the solver pushed on (an impact stopped just before the surfaces
// met is an impact). Both lists are in pair order, and so is the result.
const std::vector<Contact>& SequentialImpulseSolver::eventContacts(const std::vector<Contact>& contacts) {
  eventContacts_.clear();
  std::size_t next = 0;
  const auto pairOf = [&contacts](std::size_t index) { return BodyPair{contacts[index].a, contacts[index].b}; };
  for (const ContactManifold& manifold : manifolds_) {
    const BodyPair pair{manifold.a, manifold.b};
    while (next < contacts.size() && pairOf(next) < pair) eventContacts_.push_back(contacts[next++]);
    if (next < contacts.size() && pairOf(next) == pair) continue;
    // A pair against a mesh has a manifold per normal, and one event.
    if (!eventContacts_.empty() && BodyPair{eventContacts_.back().a, eventContacts_.back().b} == pair) continue;
    if (const std::optional<Contact> impact = speculativeImpact(manifold, solverBodies_))
      eventContacts_.push_back(*impact);
  }
  eventContacts_.insert(eventContacts_.end(), contacts.begin() + static_cast<std::ptrdiff_t>(next), contacts.end());
  return eventContacts_;
}

std::vector<ShownContact> SequentialImpulseSolver::touchedPoints(const std::vector<Contact>&) const {
  return physdbg::touchedPoints(manifolds_, settings_.linearSlop);
}

SolverStepReport SequentialImpulseSolver::solveManifolds(std::vector<RigidBody>& bodies,
                                                         const MovableBodies& movableBodies,
                                                         std::vector<ContactManifold>& manifolds,
                                                         const StepContext& step) {
  tasks_ = step.tasks;
  const std::vector<bool>& movable = movableBodies.flags;
  prepare(bodies, movable, manifolds, step.dt);
  prepareApproaches(bodies, manifolds, step.gravity, step.dt);
  const double g = step.gravity.norm();
  const std::vector<double> loads = g > 0.0 ? restingLoads(bodies, movableBodies, manifolds, touching_, -step.gravity / g, &massScales_)
                                            : std::vector<double>(manifolds.size(), 0.0);
  lastSubstep_.resize(bodies.size(), 0.0);
  buildContactIslands(manifolds, movableBodies, islands_);
  const ContactIslands& islands = islands_;
  // Each island's substeps, and its warm start rescaled to them.
  std::vector<SubstepContext> substeps(islands.size());
  std::vector<char> kinematic(islands.size(), 0);
  forEach(islands.size(), 16, [&](std::size_t i) {
    const ContactIsland island = islands[i];
    kinematic[i] = touchesKinematic(traits_, manifolds, island);
    const bool calm = !kinematic[i] && (restsAlone(manifolds, island) || restsTogether(manifolds, island));
    substeps[i] = chooseSubsteps(bodies, manifolds, island, loads, g, step, calm);
    if (!settings_.warmStarting) return;
    rescaleWarmStart(manifolds, island, movable, substeps[i].h);
    for (std::uint32_t m : island.manifolds) seedNewContact(manifolds[m], loads[m], touching_[m], g, substeps[i].h);
  });
  batchIslands(islands, substeps, kinematic);
  const std::span<IslandWork> batches(batches_.data(), batchCount_);
  // A batch that touches a kinematic body moves it through its own substeps
  // (kinematicNeighbours), so those take turns; the others run side by side.
  std::vector<std::size_t> parallel, serial;
  for (std::size_t i = 0; i < batches.size(); ++i) (batches[i].touchesKinematic ? serial : parallel).push_back(i);
  SolverStepReport report;
  {
    const StageTimer timer(report.islandSeconds);
    std::size_t parallelManifolds = 0;
    for (std::size_t k : parallel) parallelManifolds += batches[k].manifolds.size();
    // Batches go to other threads only when there is work enough to pay for
    // the bodies' cache lines travelling with them.
    const std::size_t grain = parallelManifolds < batchSplitMinimum ? parallel.size() : 1;
    forEach(parallel.size(), grain, [&](std::size_t k) { runBatch(bodies, movable, manifolds, batches[parallel[k]]); });
    for (std::size_t i : serial) runBatch(bodies, movable, manifolds, batches[i]);
  }
  // The report in island order.
  for (const SubstepContext& island : substeps) {
    report.substeps = std::max(report.substeps, island.count);
    report.contactHertz = std::max(report.contactHertz, island.contactHertz);
  }
  inBatch_.resize(bodies.size(), 0);
  for (const IslandWork& batch : batches) {
    for (std::uint32_t id : batch.bodies) inBatch_[id] = 1;
    report.largestPenetration = std::max(report.largestPenetration, batch.largestPenetration);
  }
  const SubstepContext base = flightSubsteps(step);
  integrateFreeBodies(bodies, movableBodies, base);
  for (const IslandWork& batch : batches)
    for (std::uint32_t id : batch.bodies) inBatch_[id] = 0;
  if (report.substeps == 0) {
    report.substeps = base.count;
    report.contactHertz = base.contactHertz;
  }
  return report;
}

// A body in flight takes flightSubstepCount's substeps: semi-implicit Euler
// keeps a different energy for each h, and at 4/60 s steps a flight of 8
// substeps landing in an island of 16 lost 0.04 m of an elastic ball's 6 m
// bounce each time.
SubstepContext SequentialImpulseSolver::flightSubsteps(const StepContext& step) const {
  const int count = flightSubstepCount(settings_, step.dt);
  return substepContext(step, count, std::min(settings_.contactHertz, 0.25 * count / step.dt), settings_.dampingRatio);
}

// Bodies in no manifold take the base substeps: integration alone.
void SequentialImpulseSolver::integrateFreeBodies(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                                  const SubstepContext& substeps) {
  forEach(movable.ids.size(), 256, [&](std::size_t k) {
    const std::uint32_t i = movable.ids[k];
    if (inBatch_[i]) return;
    BodyMotion motion = bodies[i].motion();
    const MotionProperties properties = bodies[i].motionProperties();
    for (int substep = 0; substep < substeps.count; ++substep) {
      integrateVelocity(motion, properties, substeps.h);
      integratePosition(motion, substeps.h);
    }
    bodies[i].setMotion(motion);
    lastSubstep_[i] = substeps.h;
  });
}

// Islands solved together: islands that take the same substeps share one
// colouring, so many small ones (boxes resting alone on the floor) still
// fill the SIMD lanes. An island that touches a kinematic body stays alone.
// A batch closes once it holds batchManifolds manifolds, so a world of many
// small islands gives batches that threads solve side by side, each through
// all its substeps with no waiting on the others (colours within one batch
// wait for each other every sweep). Islands share no movable body, so an
// island's colours and result do not depend on which batch it is in; the
// cut depends on manifold counts alone, never on the thread count.
// Batches follow the island order, and each keeps its manifolds ascending.
void SequentialImpulseSolver::batchIslands(const ContactIslands& islands, const std::vector<SubstepContext>& substeps,
                                           const std::vector<char>& kinematic) {
  batchCount_ = 0;
  std::map<std::pair<int, double>, std::size_t> open;  // by substep count and frequency
  for (std::size_t i = 0; i < islands.size(); ++i) {
    const std::pair<int, double> key{substeps[i].count, substeps[i].contactHertz};
    std::size_t index = batchCount_;
    if (!kinematic[i]) index = open.try_emplace(key, index).first->second;
    if (index == batchCount_) {
      if (batchCount_ == batches_.size()) batches_.emplace_back();
      IslandWork& batch = batches_[batchCount_++];
      batch.manifolds.clear();
      batch.bodies.clear();
      batch.substeps = substeps[i];
      batch.touchesKinematic = kinematic[i] != 0;
    }
    IslandWork& batch = batches_[index];
    const ContactIsland island = islands[i];
    batch.manifolds.insert(batch.manifolds.end(), island.manifolds.begin(), island.manifolds.end());
    batch.bodies.insert(batch.bodies.end(), island.bodies.begin(), island.bodies.end());
    if (!kinematic[i] && batch.manifolds.size() >= batchManifolds) open.erase(key);
  }
  for (std::size_t b = 0; b < batchCount_; ++b) {
    IslandWork& batch = batches_[b];
    std::sort(batch.manifolds.begin(), batch.manifolds.end());
    std::sort(batch.bodies.begin(), batch.bodies.end());
  }
}

// One batch of islands, start to end: colours, constraints, the solve, the
// figures. Kinematic neighbours are set back to their start-of-step motion
// first: an earlier batch may have moved one through its substeps.
void SequentialImpulseSolver::runBatch(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                       std::vector<ContactManifold>& manifolds, IslandWork& work) {
  const std::vector<std::uint32_t> kinematic =
      work.touchesKinematic ? kinematicNeighbours(bodies, manifolds, work.island()) : std::vector<std::uint32_t>{};
  const WideGroupPool::Loan groups(groupPool_, work.groups, work.slots);
  planIsland(bodies, manifolds, movable, work);
  solveIsland(bodies, manifolds, work, kinematic);
  for (std::uint32_t id : work.bodies) lastSubstep_[id] = work.substeps.h;
  work.largestPenetration = largestPenetration(manifolds, work.island());
}

// Colours, each colour's manifolds simd::width to a group (the speculative
// manifolds solved all points together stay single), then every
// constraint, packed into its group's lanes or kept for its single manifold.
void SequentialImpulseSolver::planIsland(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                         const std::vector<bool>& movable, IslandWork& work) {
  ConstraintColouring colouring = colourConstraints(manifolds, work.manifolds, movable, work.bodies);
  work.singles.clear();
  work.overflow = std::move(colouring.overflow);
  work.colours.assign(colouring.colours.size(), ColourWork{});
  std::vector<std::uint32_t> wideMembers;  // every group's manifolds, group after group
  std::vector<std::size_t> groupStarts;    // where each group's begin in wideMembers, then the end
  wideMembers.reserve(work.manifolds.size());
  groupStarts.reserve(work.manifolds.size() / simd::width + colouring.colours.size() + 1);
  for (std::size_t c = 0; c < colouring.colours.size(); ++c) {
    ColourWork& colour = work.colours[c];
    const std::size_t first = wideMembers.size();
    for (std::uint32_t m : colouring.colours[c])
      (settings_.wideContacts && !approaching_[m] && !overlapping_[m] && !hasLinearLocks(manifolds[m]) ? wideMembers
                                                                                                    : colour.scalar)
          .push_back(m);
    colour.firstGroup = groupStarts.size();
    for (std::size_t i = first; i < wideMembers.size(); i += simd::width) groupStarts.push_back(i);
    colour.groupCount = groupStarts.size() - colour.firstGroup;
    work.singles.insert(work.singles.end(), colour.scalar.begin(), colour.scalar.end());
  }
  groupStarts.push_back(wideMembers.size());
  work.singles.insert(work.singles.end(), work.overflow.begin(), work.overflow.end());
  work.groups.resize(groupStarts.size() - 1);
  // Each group's slots: as many as its largest manifold has points.
  std::size_t slotCount = 0;
  for (std::size_t g = 0; g + 1 < groupStarts.size(); ++g) {
    int points = 0;
    for (std::size_t i = groupStarts[g]; i < groupStarts[g + 1]; ++i)
      points = std::max(points, manifolds[wideMembers[i]].pointCount);
    work.groups[g].pointSlots = points;
    slotCount += static_cast<std::size_t>(points);
  }
  work.slots.resize(slotCount);
  std::size_t first = 0;
  for (WideManifolds& group : work.groups) {
    attachSlots(group, work.slots, first);
    first += static_cast<std::size_t>(group.pointSlots);
  }
  buildBatchConstraints(bodies, manifolds, work, wideMembers, groupStarts);
}

void SequentialImpulseSolver::solveIsland(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                          IslandWork& work, const std::vector<std::uint32_t>& kinematic) {
  const ContactIsland island = work.island();
  const SubstepContext& substeps = work.substeps;
  measureGaps(manifolds, work);
  for (int substep = 0; substep < substeps.count; ++substep) {
    integrateVelocities(island, substeps.h);
    if (settings_.warmStarting) warmStart(manifolds, work);
    for (int iteration = 0; iteration < settings_.velocityIterations; ++iteration)
      solve(manifolds, work, true, (substep + iteration) % 2 == 1);
    integratePositions(island.bodies, substeps.h);
    integratePositions(kinematic, substeps.h);
    measureGaps(manifolds, work);
    solve(manifolds, work, false, substep % 2 == 0, substep + 1 == substeps.count);
  }
  for (const WideManifolds& group : work.groups) storeWideImpulses(group, manifolds, constraints_.data(), constraintStart_, constrained_);
  applyRestitution(bodies, manifolds, island, substeps.h, substeps.h * substeps.count);
  for (std::uint32_t id : island.bodies) bodies[id].setMotion(solverBodies_[id].motion);
}

// One movable body touching something immovable. A body still in flight,
// with speculative contacts alone, keeps the full substeps: a box arriving at
// 200 m/s needs them to stop flat against a wall without spinning up.
// A body leaving the surface faster than calmSpeed (it has just bounced) or
// driven into it is not resting either: with fewer substeps its flight
// would follow another discrete path than it fell on, 1.7e-4 m lower each
// elastic bounce of a ball dropped 2.5 m.
bool SequentialImpulseSolver::restsAlone(const std::vector<ContactManifold>& manifolds,
                                         const ContactIsland& island) const {
  if (island.bodies.size() != 1) return false;
  bool touches = false;
  for (std::uint32_t m : island.manifolds) {
    const ContactManifold& manifold = manifolds[m];
    if (touchingPoints(manifold, touching_[m]) == 0) continue;
    if (!(std::abs(normalSpeed(manifold)) <= settings_.calmSpeed)) return false;
    touches = true;
  }
  return touches;
}

// The fastest a manifold's points move along its normal at the start of the
// step, b against a.
double SequentialImpulseSolver::normalSpeed(const ContactManifold& manifold) const {
  const SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  double fastest = 0.0;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    const Vec3 velocityA = a.motion.linearVelocity + a.motion.angularVelocity.cross(point.pointA - a.motion.position);
    const Vec3 velocityB = b.motion.linearVelocity + b.motion.angularVelocity.cross(point.pointB - b.motion.position);
    const double speed = (velocityB - velocityA).dot(manifold.normal);
    if (std::abs(speed) > std::abs(fastest)) fastest = speed;
  }
  return fastest;
}

// Every body calm for calmSettling (updateCalmTimes), and every contact no
// deeper than twice its resting depth (the touching distance plus the overlap
// a load may add). A body about to land, or a pile pushed apart
// from a deep overlap, is not at rest. Nor is an island whose masses span more
// than calmMassSpread: Gauss-Seidel hands a load between bodies at about
// their mass ratio per pass, so a mixed pile creeps with fewer substeps.
bool SequentialImpulseSolver::restsTogether(const std::vector<ContactManifold>& manifolds,
                                            const ContactIsland& island) const {
  constexpr double calmMassSpread = 10.0, calmSettling = 0.25;
  double lightest = std::numeric_limits<double>::infinity(), heaviest = 0.0;
  for (std::uint32_t id : island.bodies) {
    if (!(calmTime_[id] >= calmSettling)) return false;
    lightest = std::min(lightest, 1.0 / traits_[id].inverseMass);
    heaviest = std::max(heaviest, 1.0 / traits_[id].inverseMass);
  }
  if (!(heaviest <= calmMassSpread * lightest)) return false;
  for (std::uint32_t m : island.manifolds) {
    const ContactManifold& manifold = manifolds[m];
    const double deepest = -2.0 * (touching_[m] + allowedOverlap(settings_, bodySize(manifold)));
    for (int p = 0; p < manifold.pointCount; ++p)
      if (!(manifold.points[p].separation >= deepest)) return false;
  }
  return true;
}

// A body in contact that begins a step slower than calmSpeed, its spin's
// rim speed included, adds the step to its calm time; any other starts again.
void SequentialImpulseSolver::updateCalmTime(std::uint32_t id, double dt) {
  if (calmSolve_[id] + 1 != solveCount_) calmTime_[id] = 0.0;
  calmSolve_[id] = solveCount_;
  const SolverBody& body = solverBodies_[id];
  const double speed = body.motion.linearVelocity.norm() + body.motion.angularVelocity.norm() * body.size;
  calmTime_[id] = speed <= settings_.calmSpeed ? calmTime_[id] + dt : 0.0;
}

// The contact frequency is the settings' unless the most loaded touching
// point would then settle deeper than restingOverlap; substeps follow the
// frequency, since a soft contact stiffer than a quarter of the substep rate
// rings. Past maxSubsteps the frequency is capped and the overlap grows.
// A calm island takes as few substeps as its loads allow, no fewer than
// calmSubsteps, at the frequency they allow (at most the settings'). One
// whose loads need a stiffer contact than the settings' is not calm: a heavy
// load carried down a chain of contacts needs the full substeps.
SubstepContext SequentialImpulseSolver::chooseSubsteps(const std::vector<RigidBody>& bodies,
                                                       const std::vector<ContactManifold>& manifolds,
                                                       const ContactIsland& island, const std::vector<double>& loads,
                                                       double gravity, const StepContext& step, bool calm) const {
  const SolverSettings& settings = settings_;
  const double dt = step.dt;
  const int full = std::max(settings.substeps, 1);
  const int most = std::max(settings.maxSubsteps, full);
  double hertz = settings.contactHertz;
  const double fewest = std::clamp(settings.calmSubsteps, 1, full);
  // Every loaded frequency up to `enough` gives the same substeps below.
  const double enough = calm ? std::min(hertz, fewest / (4.0 * dt)) : hertz;
  const double loaded = hertz > 0.0 && settings.restingOverlap > 0.0 && most > full
                            ? loadedHertz(bodies, manifolds, island, loads, gravity, enough)
                            : 0.0;
  if (calm && loaded <= hertz) {
    const double needed = std::ceil(4.0 * loaded * dt - 1e-9);
    const int count = static_cast<int>(std::clamp(needed, fewest, static_cast<double>(full)));
    return substepContext(step, count, std::min(hertz, 0.25 * count / dt), settings.dampingRatio);
  }
  hertz = std::max(hertz, loaded);
  // Substeps that make `hertz` a quarter of the substep rate, within bounds.
  const double wanted = std::ceil(4.0 * hertz * dt - 1e-9);
  const int substeps = static_cast<int>(std::clamp(wanted, static_cast<double>(full), static_cast<double>(most)));
  return substepContext(step, substeps, std::min(hertz, 0.25 * substeps / dt), settings.dampingRatio);
}

// The frequency at which the island's most demanding touching point, by
// (force / effective mass) / allowed overlap, settles at its allowed overlap.
// The force is a point's share of what its manifold holds: the weight it
// holds up (restingLoads), or for a manifold that holds none up, what it
// carried last step (carriedForce). The second sees a light body squeezed
// sideways, say between a heavy pile and a wall; weights are steadier than
// last step's impulses, so they decide wherever they can.
//
// The effective masses need each point's normal row, which is built here
// (the batches build the rest later). A bound that needs none comes first
// (manifoldDemand): when even it stays within `enough`, which the caller
// treats like any lower frequency, it is the answer; otherwise a manifold
// whose bound cannot beat the largest exact demand so far is skipped.
double SequentialImpulseSolver::loadedHertz(const std::vector<RigidBody>& bodies,
                                            const std::vector<ContactManifold>& manifolds, const ContactIsland& island,
                                            const std::vector<double>& loads, double gravity, double enough) const {
  const auto hertzOf = [](double demand) { return std::sqrt(demand) / (2.0 * std::numbers::pi); };
  double bound = 0.0;
  for (std::uint32_t m : island.manifolds)
    bound = std::max(bound, manifoldDemand(bodies, manifolds, m, loads, gravity, true));
  if (hertzOf(bound) <= enough) return hertzOf(bound);
  double demand = 0.0;
  for (std::uint32_t m : island.manifolds)
    if (!(manifoldDemand(bodies, manifolds, m, loads, gravity, true) <= demand))
      demand = std::max(demand, manifoldDemand(bodies, manifolds, m, loads, gravity, false));
  return hertzOf(demand);
}

// force / mass / allowed at the manifold's most demanding touching point (0
// where it holds nothing), or with `bound`, an upper bound of it that builds
// no row: 1 / mass = J M^-1 J^T is at most the inverse masses plus, per body,
// |arm|^2 times its inverse inertia's largest absolute row sum (|arm x n| <=
// |arm|; a symmetric matrix stretches no vector by more than that sum).
double SequentialImpulseSolver::manifoldDemand(const std::vector<RigidBody>& bodies,
                                               const std::vector<ContactManifold>& manifolds, std::uint32_t m,
                                               const std::vector<double>& loads, double gravity, bool bound) const {
  const ContactManifold& manifold = manifolds[m];
  const int touching = touchingPoints(manifold, touching_[m]);
  if (touching == 0) return 0.0;
  const double force = (loads[m] > 0.0 ? loads[m] * gravity : carriedForce(manifold)) / touching;
  if (!(force > 0.0)) return 0.0;
  const double allowed = allowedOverlap(settings_, bodySize(manifold));
  if (bound) {
    const BodyTraits &a = traits_[manifold.a], &b = traits_[manifold.b];
    const auto [scaleA, scaleB] = massScales_[m];
    double armA = 0.0, armB = 0.0;
    for (int p = 0; p < manifold.pointCount; ++p) {
      Vec3 pointArmA, pointArmB;
      pointArms(manifold, p, a.position, b.position, settings_.linearSlop, pointArmA, pointArmB);
      armA = std::max(armA, pointArmA.squaredNorm());
      armB = std::max(armB, pointArmB.squaredNorm());
    }
    const double give = scaleA * a.inverseMass + scaleB * b.inverseMass + armA * scaleA * a.inverseInertiaBound +
                        armB * scaleB * b.inverseInertiaBound;
    // The margin covers the rounding of the exact sum.
    return force * give * (1.0 + 1e-6) / allowed;
  }
  PointConstraint rows[ContactManifold::maxPoints];
  buildNormalRows(bodies, manifold, m, 1, rows);
  double demand = 0.0;
  for (int p = 0; p < manifold.pointCount; ++p)
    if (rows[p].normalMass > 0.0) demand = std::max(demand, force / rows[p].normalMass / allowed);
  return demand;
}

// The force (N) a manifold held through last step's final substep: the
// impulses it carries into this step over that substep's length. An impact's
// impulse counts too, for the one step after it: a body that lands hard on a
// light one gets the stiffer contact it needs at once.
double SequentialImpulseSolver::carriedForce(const ContactManifold& manifold) const {
  double previous = 0.0, impulse = 0.0;
  for (std::uint32_t id : {manifold.a, manifold.b})
    if (traits_[id].movable) previous = std::max(previous, lastSubstep_[id]);
  for (int p = 0; p < manifold.pointCount; ++p) impulse += manifold.points[p].normalImpulse;
  return previous > 0.0 ? impulse / previous : 0.0;
}

// The middle of a body's three extents: a cube's edge, a plate's width, a
// rod's thickness. Of the two bodies, the smaller movable one.
double SequentialImpulseSolver::bodySize(const ContactManifold& manifold) const {
  const BodyTraits &bodyA = traits_[manifold.a], &bodyB = traits_[manifold.b];
  return std::min(bodyA.inverseMass > 0.0 ? bodyA.size : bodyB.size, bodyB.inverseMass > 0.0 ? bodyB.size : bodyA.size);
}

// Impulses carried from the last step were found over its substep (the
// one its bodies took); a step with a different substep scales them so they
// still mean the same force.
void SequentialImpulseSolver::rescaleWarmStart(std::vector<ContactManifold>& manifolds, const ContactIsland& island,
                                               const std::vector<bool>& movable, double substep) const {
  for (std::uint32_t m : island.manifolds) {
    ContactManifold& manifold = manifolds[m];
    const double previous = std::max(movable[manifold.a] ? lastSubstep_[manifold.a] : 0.0,
                                     movable[manifold.b] ? lastSubstep_[manifold.b] : 0.0);
    if (previous == 0.0 || previous == substep) continue;
    const double scale = substep / previous;
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      point.normalImpulse *= scale;
      point.tangentImpulse[0] *= scale;
      point.tangentImpulse[1] *= scale;
    }
  }
}

// Each body's working copy and traits, then each manifold's tangents and
// touching distance. Calm times are updated in the same pass, while the
// body's copy is still in this thread's cache (a separate serial pass over
// 16000 bodies took 0.2 ms, and 0.3 ms when another thread had written them).
void SequentialImpulseSolver::prepare(const std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                                      std::vector<ContactManifold>& manifolds, double dt) {
  calmTime_.resize(bodies.size(), 0.0);
  calmSolve_.resize(bodies.size(), 0);
  ++solveCount_;
  listed_.resize(bodies.size(), 0);
  for (std::uint32_t id : listedIds_) listed_[id] = 0;
  listedIds_.clear();
  for (const ContactManifold& manifold : manifolds)
    for (std::uint32_t id : {manifold.a, manifold.b})
      if (!listed_[id]) {
        listed_[id] = 1;
        listedIds_.push_back(id);
      }
  ranks_.assign(listedIds_, bodies.size());  // in the order the manifolds list them: any fixed order will do
  solverBodies_.resize(ranks_);
  traits_.resize(ranks_);
  motionProperties_.resize(ranks_);
  startVelocities_.resize(ranks_);
  impactVelocities_.resize(ranks_);
  forEach(listedIds_.size(), 256, [&](std::size_t k) {
    const std::uint32_t id = listedIds_[k];
    SolverBody& body = solverBodies_[id];
    const RigidBody& source = bodies[id];
    body.movable = movable[id];
    body.inverseMass = movable[id] ? source.inverseMass() : 0.0;
    body.inverseInertia = movable[id] ? source.worldInverseInertia() : Mat3::Zero();
    body.inverseInertiaBound = body.inverseInertia.cwiseAbs().rowwise().sum().maxCoeff();
    for (int axis = 0; axis < 3; ++axis) {
      body.linearMask[axis] = source.lockTranslation()[axis] ? 0.0 : 1.0;
      body.angularMask[axis] = source.lockRotation()[axis] ? 0.0 : 1.0;
    }
    body.motion = source.motion();
    startVelocities_[id] = {body.motion.linearVelocity, body.motion.angularVelocity};
    motionProperties_[id] = source.motionProperties();
    Vec3 extents = source.collider().localBounds().halfExtents() * 2.0;
    std::sort(extents.data(), extents.data() + 3);
    body.size = extents[1];
    body.rotation = source.orientation().toRotationMatrix();
    body.startOrientation = source.orientation();
    body.gapTurn = gapTurnOf(source.collider().kind());
    traits_[id] = {body.motion.position, body.inverseMass, body.inverseInertiaBound, body.size,
                   source.isKinematic(), body.movable};
    updateCalmTime(id, dt);
  });
  // Room for every point's constraint, manifold after manifold; only the
  // batches' single and bouncing manifolds write theirs
  // (sequential_impulse_prepare.cpp), so the room is not zeroed: pages no
  // manifold writes are never touched.
  constraintStart_.resize(manifolds.size() + 1);
  constraintStart_[0] = 0;
  for (std::size_t m = 0; m < manifolds.size(); ++m)
    constraintStart_[m + 1] = constraintStart_[m] + static_cast<std::size_t>(manifolds[m].pointCount);
  constraints_.resize(constraintStart_.back());
  constrained_.assign(manifolds.size(), 0);
  tangents_.resize(manifolds.size());
  touching_.resize(manifolds.size());
  massScales_ = supportMassScales(manifolds);
  forEach(manifolds.size(), 256, [&](std::size_t m) {
    ContactManifold& manifold = manifolds[m];
    tangentBasis(manifold.normal, tangents_[m][0], tangents_[m][1]);
    // Touching, for holding weight: within the slop, or within a tenth of
    // the smaller body for bodies not much bigger than the slop.
    touching_[m] = std::min(settings_.linearSlop, 0.1 * bodySize(manifold));
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      point.stepNormalImpulse = 0.0;
      if (!settings_.warmStarting) point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
    }
  });
}

void SequentialImpulseSolver::integrateVelocities(const ContactIsland& island, double h) {
  forEach(island.bodies.size(), 256, [&](std::size_t i) {
    const std::uint32_t id = island.bodies[i];
    integrateVelocity(solverBodies_[id].motion, motionProperties_[id], h);
  });
}

// Kinematic bodies move on their own through the step (World moves them after
// the solve). An island sees those it touches move with its own substeps, from
// their start-of-step pose, so gaps to them stay true; an island that touches
// none pays nothing.
std::vector<std::uint32_t> SequentialImpulseSolver::kinematicNeighbours(const std::vector<RigidBody>& bodies,
                                                                         const std::vector<ContactManifold>& manifolds,
                                                                         const ContactIsland& island) {
  std::vector<std::uint32_t> kinematic;
  for (std::uint32_t m : island.manifolds)
    for (std::uint32_t id : {manifolds[m].a, manifolds[m].b})
      if (bodies[id].isKinematic() && std::find(kinematic.begin(), kinematic.end(), id) == kinematic.end())
        kinematic.push_back(id);
  for (std::uint32_t id : kinematic) {
    solverBodies_[id].motion = bodies[id].motion();
    solverBodies_[id].rotation = bodies[id].orientation().toRotationMatrix();
  }
  return kinematic;
}

void SequentialImpulseSolver::integratePositions(std::span<const std::uint32_t> ids, double h) {
  forEach(ids.size(), 256, [&](std::size_t i) {
    SolverBody& body = solverBodies_[ids[i]];
    const Eigen::Vector4d before = body.motion.orientation.coeffs();
    integratePosition(body.motion, h);
    if (body.motion.orientation.coeffs() != before) body.rotation = gapRotation(body);
  });
}

// Poses change only when positions are integrated, once per substep, so the
// gaps are measured then and shared by every sweep until the next move: a
// wide group's straight into its lanes (lanes past a manifold's points hold
// 0, and their zero masses leave them out of the solve), a single
// manifold's into its points' constraints.
void SequentialImpulseSolver::measureGaps(const std::vector<ContactManifold>& manifolds, IslandWork& work) {
  forEach(work.groups.size(), 64, [&](std::size_t g) { measureWideGaps(work.groups[g], solverBodies_.byRank()); });
  forEach(work.singles.size(), 256, [&](std::size_t i) {
    const std::uint32_t m = work.singles[i];
    double gaps[ContactManifold::maxPoints];
    manifoldGaps(manifolds[m], gaps);
    for (int p = 0; p < manifolds[m].pointCount; ++p) pointConstraints(m)[p].gap = gaps[p];
  });
}

void SequentialImpulseSolver::warmStart(std::vector<ContactManifold>& manifolds, IslandWork& work) {
  runColours(
      work, [this](std::span<WideManifolds> groups) { warmStartWide(groups, solverBodies_.byRank()); },
      [&](std::uint32_t m) { warmStartManifold(manifolds[m], m); });
}

void SequentialImpulseSolver::warmStartManifold(ContactManifold& manifold, std::size_t m) {
  for (int p = 0; p < manifold.pointCount; ++p) {
    ManifoldPoint& point = manifold.points[p];
    const PointConstraint& c = pointConstraints(m)[p];
    applyNormal(manifold, c, point, point.normalImpulse);
    applyRow(manifold, c, tangents_[m][0], 1, point.tangentImpulse[0]);
    applyRow(manifold, c, tangents_[m][1], 2, point.tangentImpulse[1]);
  }
}

void SequentialImpulseSolver::solveNormals(ContactManifold& manifold, std::size_t m,
                                           const SubstepContext& substeps, bool useBias, bool reversed) {
  const double substep = substeps.h;
  const Softness& softness = substeps.softness;
  for (int visit = 0; visit < manifold.pointCount; ++visit) {
    const int p = reversed ? manifold.pointCount - 1 - visit : visit;
    ManifoldPoint& point = manifold.points[p];
    PointConstraint& c = pointConstraints(m)[p];
    const double gap = c.gap;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (gap > 0.0) {
      bias = gap / substep;
    } else if (useBias) {
      bias = std::max(softness.biasRate * gap, -settings_.maxPushSpeed);
      massScale = softness.massScale;
      impulseScale = softness.impulseScale;
    }
    const double normalVelocity = rowVelocity(manifold, c, manifold.normal, 0);
    const double impulse = -c.normalMass * massScale * (normalVelocity + bias) - impulseScale * point.normalImpulse;
    const double total = std::max(point.normalImpulse + impulse, 0.0);
    applyNormal(manifold, c, point, total - point.normalImpulse);
    point.normalImpulse = total;
    c.largestImpulse = std::max(c.largestImpulse, total);
  }
}

// All points of the manifold at once: the impulses that bring every point
// exactly to its gap (or, once touching, stop it) in this substep, from the
// pseudo-inverse of the manifold's 4x4 normal mass matrix (four coplanar
// points have only three independent motions, so the matrix is singular).
// Two of the complementarity cases are tried: every point pushing, and none
// (the usual answer once the warm-started stopping impulse must be taken
// back). Anything else is left to the point-by-point solve.
bool SequentialImpulseSolver::solveApproachTogether(ContactManifold& manifold, std::size_t m, double substep) {
  const int count = manifold.pointCount;
  Eigen::Vector4d target = Eigen::Vector4d::Zero(), impulse = Eigen::Vector4d::Zero();
  for (int p = 0; p < count; ++p) {
    const PointConstraint& c = pointConstraints(m)[p];
    const double gap = std::max(c.gap, 0.0);
    target[p] = rowVelocity(manifold, c, manifold.normal, 0) + gap / substep;
    impulse[p] = manifold.points[p].normalImpulse;
  }
  // A case holds when no value is below zero by more than rounding of the
  // numbers it came from. When the exact answer is zero (the relax sweep
  // taking back the stopping impulse just given), rounding alone decides
  // the sign: a box tilted by 1e-12 rad failed both cases, fell back to the
  // point-by-point solve and left a 200 m/s impact spinning at 11 rad/s.
  const auto anyNegative = [count](const Eigen::Vector4d& values, double scale) {
    const double allowed = -kApproachRounding * scale;
    for (int p = 0; p < count; ++p)
      if (values[p] < allowed) return true;
    return false;
  };
  const auto largest = [count](const Eigen::Vector4d& values) { return largestOf(values, count); };
  const Eigen::Matrix4d& mass = approachMass_[m];
  Eigen::Vector4d change = -(approachInverse_[m] * target);
  if (anyNegative(impulse + change, largest(impulse) + largest(change))) {
    const Eigen::Vector4d allPush = change;
    // None pushing: removing every impulse must leave every point opening.
    change = -impulse;
    const Eigen::Vector4d response = mass * change;
    if (anyNegative(target + response, largest(target) + largest(response)) &&
        !solveMixedApproach(mass, target, impulse, allPush, count, change)) {
      return false;
    }
  }
  for (int p = 0; p < count; ++p) {
    PointConstraint& c = pointConstraints(m)[p];
    ManifoldPoint& point = manifold.points[p];
    const double total = std::max(point.normalImpulse + change[p], 0.0);  // a rounding-sized pull is dropped
    applyNormal(manifold, c, point, total - point.normalImpulse);
    point.normalImpulse = total;
    c.largestImpulse = std::max(c.largestImpulse, point.normalImpulse);
  }
  return true;
}

// A face sunk deeper than the slop at every point, pushed out (and, in the
// relax sweep, stopped) at all its points at once: the soft rows of
// solveNormals with the manifold's normal mass matrix in place of each
// point's own, from its pseudo-inverse, so a box sunk flat is pushed
// straight out. Point by point, the first point took the most, the box
// tilted, its corners slid and friction walked it sideways. Anything that
// would pull, or a point that came apart, is left to the point-by-point
// solve.
bool SequentialImpulseSolver::solveOverlapTogether(ContactManifold& manifold, std::size_t m,
                                                   const SubstepContext& substeps, bool useBias) {
  const int count = manifold.pointCount;
  const Softness& softness = substeps.softness;
  Eigen::Vector4d error = Eigen::Vector4d::Zero(), impulse = Eigen::Vector4d::Zero();
  for (int p = 0; p < count; ++p) {
    const PointConstraint& c = pointConstraints(m)[p];
    if (c.gap > 0.0) return false;
    const double bias = useBias ? std::max(softness.biasRate * c.gap, -settings_.maxPushSpeed) : 0.0;
    error[p] = rowVelocity(manifold, c, manifold.normal, 0) + bias;
    impulse[p] = manifold.points[p].normalImpulse;
  }
  const double massScale = useBias ? softness.massScale : 1.0;
  const double impulseScale = useBias ? softness.impulseScale : 0.0;
  const Eigen::Vector4d change = -massScale * (approachInverse_[m] * error) - impulseScale * impulse;
  const double scale = largestOf(impulse, count) + largestOf(change, count);
  for (int p = 0; p < count; ++p)
    if (impulse[p] + change[p] < -kApproachRounding * scale) return false;
  for (int p = 0; p < count; ++p) {
    PointConstraint& c = pointConstraints(m)[p];
    ManifoldPoint& point = manifold.points[p];
    const double total = std::max(point.normalImpulse + change[p], 0.0);
    applyNormal(manifold, c, point, total - point.normalImpulse);
    point.normalImpulse = total;
    c.largestImpulse = std::max(c.largestImpulse, total);
  }
  return true;
}

// Solving the points of a manifold one by one hands the first the whole
// stop of an approaching body: a box arriving face first at 200 m/s would
// leave spinning at 4.9 rad/s. Manifolds whose points are all still apart
// and close fast are solved together instead (solveApproachTogether). The
// spin grows with the speed, so below slowApproach (2.5e-3 rad/s at most)
// the soft contacts that follow absorb it, and the manifold joins the SIMD
// lanes: a pyramid's neighbours, a hair apart side by side, are most of the
// manifolds still apart, and they barely move.
void SequentialImpulseSolver::prepareApproaches(const std::vector<RigidBody>& bodies,
                                                const std::vector<ContactManifold>& manifolds, const Vec3& gravity,
                                                double dt) {
  constexpr double slowApproach = 0.1;  // m/s
  approaching_.assign(manifolds.size(), 0);
  overlapping_.assign(manifolds.size(), 0);
  approachInverse_.resize(manifolds.size());
  approachMass_.resize(manifolds.size());
  forEach(manifolds.size(), 256, [&](std::size_t m) {
    const ContactManifold& manifold = manifolds[m];
    if (manifold.pointCount < 2) return;
    bool apart = true, deep = true;
    for (int p = 0; p < manifold.pointCount; ++p) {
      apart = apart && manifold.points[p].separation > 0.0;
      deep = deep && manifold.points[p].separation < -settings_.linearSlop;
    }
    if (deep) {
      PointConstraint rows[ContactManifold::maxPoints];
      buildNormalRows(bodies, manifold, m, 1, rows);
      approachMass_[m] =
          normalMassMatrix(manifold, rows, solverBodies_[manifold.a].linearMask, solverBodies_[manifold.b].linearMask);
      approachInverse_[m] = pseudoInverse(approachMass_[m]);
      overlapping_[m] = 1;
      return;
    }
    if (!apart) return;
    const Vec3& normal = manifold.normal;
    // Closing speed at the fastest point, plus what gravity may add this
    // step. The speed along the normal needs the arms alone.
    PointConstraint rows[ContactManifold::maxPoints];
    buildNormalRows(bodies, manifold, m, 0, rows);
    double closing = std::abs(gravity.dot(normal)) * dt;
    double fastest = 0.0;
    for (int p = 0; p < manifold.pointCount; ++p) {
      rows[p].crossA[0] = rows[p].armA.cross(normal);
      rows[p].crossB[0] = rows[p].armB.cross(normal);
      fastest = std::max(fastest, -rowVelocity(manifold, rows[p], normal, 0));
    }
    closing += fastest;
    if (!(closing > slowApproach)) return;
    buildNormalRows(bodies, manifold, m, 1, rows);
    const Eigen::Matrix4d mass =
        normalMassMatrix(manifold, rows, solverBodies_[manifold.a].linearMask, solverBodies_[manifold.b].linearMask);
    approachMass_[m] = mass;
    approachInverse_[m] = pseudoInverse(mass);
    approaching_[m] = 1;
  });
}

// One sweep over every point: the normal constraint (soft push-out while
// overlapping with `useBias`, exact closing of the gap while apart), then
// Coulomb friction clamped to the cone |f| <= mu * normal impulse.
// Every other sweep visits the points of each manifold in reverse: a fixed
// order hands the first corner the largest share of every correction, which
// tilts a stack the same way step after step until it walks sideways.
void SequentialImpulseSolver::solve(std::vector<ContactManifold>& manifolds, IslandWork& work, bool useBias,
                                    bool reversed, bool stepEnds) {
  const SubstepContext& substeps = work.substeps;
  const WideSweep sweep{&substeps, settings_.maxPushSpeed, useBias, reversed, stepEnds};
  runColours(
      work, [this, &sweep](std::span<WideManifolds> groups) { solveWide(groups, solverBodies_.byRank(), sweep); },
      [&](std::uint32_t m) {
        ContactManifold& manifold = manifolds[m];
        // The step's last relax sweep leaves a manifold that no point has
        // reached alone: pushing there would only slow a body that arrives
        // next step (a ball 1.8 mm above the floor lost 11% of its speed and
        // raised begin before it touched). Next step's solve stops it.
        const bool leave = stepEnds && !reachedAny(m, manifold.pointCount);
        const bool together = approaching_[m] ? solveApproachTogether(manifold, m, substeps.h)
                                              : overlapping_[m] && solveOverlapTogether(manifold, m, substeps, useBias);
        if (!leave && !together) solveNormals(manifold, m, substeps, useBias, reversed);
        solveFriction(manifold, m, reversed);
      });
}

bool SequentialImpulseSolver::reachedAny(std::size_t m, int count) const {
  for (int p = 0; p < count; ++p)
    if (pointConstraints(m)[p].gap <= kReachedGap) return true;
  return false;
}

void SequentialImpulseSolver::solveFriction(ContactManifold& manifold, std::size_t m, bool reversed) {
  for (int visit = 0; visit < manifold.pointCount; ++visit) {
    const int p = reversed ? manifold.pointCount - 1 - visit : visit;
    ManifoldPoint& point = manifold.points[p];
    const PointConstraint& c = pointConstraints(m)[p];
    double velocity[2], tangentImpulse[2];
    for (int t = 0; t < 2; ++t) {
      velocity[t] = rowVelocity(manifold, c, tangents_[m][t], t + 1);
      tangentImpulse[t] = point.tangentImpulse[t] - c.tangentMass[t] * velocity[t];
    }
    const double limit = c.friction * point.normalImpulse;
    const double squared = tangentImpulse[0] * tangentImpulse[0] + tangentImpulse[1] * tangentImpulse[1];
    if (squared > limit * limit && squared > 0.0) {
      // Sliding past what the full friction could stop: Coulomb's force
      // opposes the sliding velocity. The two rows' unequal masses turn their
      // joint update away from it (a spinning box's corner torque came out
      // 1.35% weak), so there it sets only the magnitude. A point the limit
      // could stop keeps the joint update, which remembers its last force.
      const double speed = velocity[0] * velocity[0] + velocity[1] * velocity[1];
      const double least = std::min(c.tangentMass[0], c.tangentMass[1]);
      if (speed * least * least > limit * limit) {
        const double scale = -limit / std::sqrt(speed);
        tangentImpulse[0] = velocity[0] * scale;
        tangentImpulse[1] = velocity[1] * scale;
      } else {
        const double scale = limit / std::sqrt(squared);
        tangentImpulse[0] *= scale;
        tangentImpulse[1] *= scale;
      }
    }
    applyRow(manifold, c, tangents_[m][0], 1, tangentImpulse[0] - point.tangentImpulse[0]);
    applyRow(manifold, c, tangents_[m][1], 2, tangentImpulse[1] - point.tangentImpulse[1]);
    point.tangentImpulse[0] = tangentImpulse[0];
    point.tangentImpulse[1] = tangentImpulse[1];
  }
}

// Restitution, once per island after its substeps. A bounce is one event
// for the whole face that makes it, so each manifold's bouncing points are
// solved together (bounce.h): one point at a time, the first corner took
// the whole bounce and a box landing flat left spinning. An island where
// the impact must travel on through bodies in contact (a row of touching
// elastic balls) passes it on from body to body instead (passImpactsOn).
void SequentialImpulseSolver::applyRestitution(const std::vector<RigidBody>& bodies,
                                               std::vector<ContactManifold>& manifolds, const ContactIsland& island,
                                               double substep, double dt) {
  if (passesImpactsOn(bodies, manifolds, island)) {
    passImpactsOn(bodies, manifolds, island, dt);
    return;
  }
  for (std::uint32_t m : island.manifolds) {
    // A wide manifold keeps its constraints only if it may bounce.
    if (constrained_[m]) bounceManifold(manifolds[m], m, substep);
  }
}

// How fast forces and gravity close the pair at the point, m/s^2 (bounce.h's pull).
double SequentialImpulseSolver::closingPull(const ContactManifold& manifold, const PointConstraint& c) const {
  const auto accelerationAt = [this](std::uint32_t id, const Vec3& arm) -> Vec3 {
    if (!solverBodies_[id].movable) return Vec3::Zero();
    const MotionProperties& properties = motionProperties_[id];
    return properties.acceleration + properties.angularAcceleration.cross(arm);
  };
  return -(accelerationAt(manifold.b, c.armB) - accelerationAt(manifold.a, c.armA)).dot(manifold.normal);
}

// Points that pushed this step, bounce (their approach at the start of the
// step was fast enough) and ended within the touching slop (a corner's
// anchor, lifted a fraction of a millimetre by the turn after its impact,
// still bounces): a mask of them.
int SequentialImpulseSolver::bouncingPoints(const ContactManifold& manifold, std::size_t m,
                                            double (&gaps)[ContactManifold::maxPoints]) const {
  if (!mayBounce(manifold, m)) return 0;
  const PointConstraint* rows = pointConstraints(m);
  manifoldGaps(manifold, gaps);
  int mask = 0;
  for (int p = 0; p < manifold.pointCount; ++p)
    if (rows[p].restitution != 0.0 && rows[p].largestImpulse != 0.0 && gaps[p] <= settings_.linearSlop) mask |= 1 << p;
  return mask;
}

// Whether any point may bounce, before its gap is measured: it pushed and
// its approach was fast enough. Most manifolds fail this, and cheaply.
bool SequentialImpulseSolver::mayBounce(const ContactManifold& manifold, std::size_t m) const {
  if (!constrained_[m]) return false;
  const PointConstraint* rows = pointConstraints(m);
  for (int p = 0; p < manifold.pointCount; ++p)
    if (rows[p].restitution != 0.0 && rows[p].largestImpulse != 0.0) return true;
  return false;
}

// The bouncing points leave at bounceSpeed, all at once.
void SequentialImpulseSolver::bounceManifold(ContactManifold& manifold, std::size_t m, double substep) {
  double gaps[ContactManifold::maxPoints];
  const int mask = bouncingPoints(manifold, m, gaps);
  if (mask == 0) return;
  const PointConstraint* rows = pointConstraints(m);
  Eigen::Vector4d error = Eigen::Vector4d::Zero(), impulse = Eigen::Vector4d::Zero();
  for (int p = 0; p < manifold.pointCount; ++p) {
    if (!((mask >> p) & 1)) continue;
    const PointConstraint& c = rows[p];
    const double target = bounceSpeed({manifold.points[p].separation, c.approachVelocity, closingPull(manifold, c),
                                       gaps[p], c.restitution, substep});
    error[p] = rowVelocity(manifold, c, manifold.normal, 0) - target;
    impulse[p] = manifold.points[p].normalImpulse;
  }
  const Eigen::Matrix4d mass =
      normalMassMatrix(manifold, rows, solverBodies_[manifold.a].linearMask, solverBodies_[manifold.b].linearMask);
  const Eigen::Vector4d change = bounceImpulses(mass, error, impulse, manifold.pointCount, mask);
  for (int p = 0; p < manifold.pointCount; ++p) {
    if (!((mask >> p) & 1)) continue;
    ManifoldPoint& point = manifold.points[p];
    const double total = std::max(point.normalImpulse + change[p], 0.0);
    applyNormal(manifold, rows[p], point, total - point.normalImpulse);
    point.normalImpulse = total;
  }
}

namespace {


}  // namespace

// A manifold that takes part in the step's impacts: it pushed, or it ends
// the step touching (within the slop). A row of touching balls struck at the
// very end of a step has pushed only on its first contacts by then.
bool SequentialImpulseSolver::takesPartInImpacts(const ContactManifold& manifold) const {
  double gaps[ContactManifold::maxPoints];
  manifoldGaps(manifold, gaps);
  for (int p = 0; p < manifold.pointCount; ++p)
    if (manifold.points[p].stepNormalImpulse > 0.0 || gaps[p] <= settings_.linearSlop) return true;
  return false;
}

// A bounce whose impact must travel on: some manifold bounces, and another
// that takes part (takesPartInImpacts) joins two movable bodies with a bouncy material but
// did not bounce itself (they touched, still). Bouncing the first alone
// leaves the row behind it moving together: Newton's cradle lost half its
// energy, the first ball came back and the rest left as one. Only along a
// row: an island of at most kImpactRowContacts contacts in which no movable
// body touches more than two others. In a pile, impacts ordered one after
// another are neither what happens (they overlap in time) nor affordable
// (a settling pile of 1000 balls took 30 times as long a step and never
// came to rest); a pile bounces manifold by manifold.
bool SequentialImpulseSolver::passesImpactsOn(const std::vector<RigidBody>& bodies,
                                              const std::vector<ContactManifold>& manifolds,
                                              const ContactIsland& island) const {
  constexpr std::size_t kImpactRowContacts = 64;
  if (island.bodies.size() < 2 || island.manifolds.size() > kImpactRowContacts) return false;
  if (std::none_of(island.manifolds.begin(), island.manifolds.end(),
                   [&](std::uint32_t m) { return mayBounce(manifolds[m], m); }))
    return false;
  bool bounces = false, carries = false;
  std::vector<std::pair<std::uint32_t, int>> touches;  // movable body, movable neighbours pushed on
  const auto touch = [&touches](std::uint32_t id) {
    for (auto& [body, count] : touches)
      if (body == id) return ++count;
    touches.emplace_back(id, 1);
    return 1;
  };
  for (std::uint32_t m : island.manifolds) {
    const ContactManifold& manifold = manifolds[m];
    if (!takesPartInImpacts(manifold)) continue;
    const bool movable = solverBodies_[manifold.a].movable && solverBodies_[manifold.b].movable;
    if (movable && (touch(manifold.a) > 2 || touch(manifold.b) > 2)) return false;
    double gaps[ContactManifold::maxPoints];
    if (bouncingPoints(manifold, m, gaps) != 0) {
      bounces = true;
    } else if (movable) {
      carries = carries || combineMaterials(bodies[manifold.a].material(), bodies[manifold.b].material(),
                                            settings_.restitutionCombine(), settings_.frictionCombine())
                                   .restitution > 0.0;
    }
  }
  return bounces && carries;
}

// The impacts of the step as rigid bodies meet, one contact after another
// (Guendelman's sequential collisions): from the velocities the island's
// bodies would end the step with untouched (start of step plus forces and
// gravity), each contact still approaching takes the impulse that sends it
// apart at e times its approach (at once over its points, bounce.h), or,
// slower than the bounce threshold or with e = 0, just stops it; until none
// approaches. An equal row of elastic balls passes the striker's speed down
// the row to the far ball. These impulses replace the normal impulses the
// substeps gave the island's contacts that take part (each point's step total), so
// friction stays and each point's total says what it gave.
void SequentialImpulseSolver::passImpactsOn(const std::vector<RigidBody>& bodies,
                                            std::vector<ContactManifold>& manifolds, const ContactIsland& island,
                                            double dt) {
  std::vector<ImpactContact> contacts;
  for (std::uint32_t m : island.manifolds) {
    const ContactManifold& manifold = manifolds[m];
    if (!takesPartInImpacts(manifold)) continue;
    ImpactContact& contact = contacts.emplace_back();
    contact.manifold = m;
    buildNormalRows(bodies, manifold, m, 1, contact.rows);
    contact.mass =
        normalMassMatrix(manifold, contact.rows, solverBodies_[manifold.a].linearMask, solverBodies_[manifold.b].linearMask);
    contact.restitution = combineMaterials(bodies[manifold.a].material(), bodies[manifold.b].material(),
                                           settings_.restitutionCombine(), settings_.frictionCombine())
                              .restitution;
  }
  const std::vector<Eigen::Vector4d> impacts = sequentialImpacts(manifolds, contacts, dt);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    ContactManifold& manifold = manifolds[contacts[k].manifold];
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      applyNormal(manifold, contacts[k].rows[p], point, impacts[k][p] - point.stepNormalImpulse);
      // Between two movable bodies the warm start (the last substep's
      // impulse) goes: it held them together through the impact that now
      // sends them apart, and would shove them at the next step's start (a
      // struck row crept back at 0.015 m/s). Against something immovable it
      // stays: it carries the weight there, and a settling pile of balls
      // that lost it at every small impact jittered (ten times the kinetic
      // energy after 7 s).
      if (solverBodies_[manifold.a].movable && solverBodies_[manifold.b].movable)
        point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = 0.0;
    }
  }
}

// sequentialImpacts' run from each body's free velocities at the end of the
// step, in contact order, until no point approaches by more than a 1e-12
// share of the fastest speed (or 10,000 sweeps, where a chain has no end).
// Returns each contact's total impulses; touches only its own copy of the
// velocities.
std::vector<Eigen::Vector4d> SequentialImpulseSolver::sequentialImpacts(const std::vector<ContactManifold>& manifolds,
                                                                        const std::vector<ImpactContact>& contacts,
                                                                        double dt) {
  std::vector<Eigen::Vector4d> totals(contacts.size(), Eigen::Vector4d::Zero());
  double fastest = 0.0;
  for (const ImpactContact& contact : contacts)
    for (std::uint32_t id : {manifolds[contact.manifold].a, manifolds[contact.manifold].b}) {
      // Other batches share immovable bodies: those are read, never written.
      if (!solverBodies_[id].movable) continue;
      const MotionProperties& properties = motionProperties_[id];
      impactVelocities_[id] = {startVelocities_[id].first + properties.acceleration * dt,
                               startVelocities_[id].second + properties.angularAcceleration * dt};
      fastest = std::max(fastest, impactVelocities_[id].first.norm());
    }
  const double still = 1e-12 * std::max(fastest, 1e-300);
  constexpr int mostSweeps = 10'000;
  for (int sweep = 0; sweep < mostSweeps; ++sweep) {
    bool moved = false;
    for (std::size_t k = 0; k < contacts.size(); ++k)
      moved = impactOnce(manifolds[contacts[k].manifold], contacts[k], still, totals[k]) || moved;
    if (!moved) break;
  }
  return totals;
}

// One contact of sequentialImpacts: its approaching points meet.
bool SequentialImpulseSolver::impactOnce(const ContactManifold& manifold, const ImpactContact& contact, double still,
                                         Eigen::Vector4d& total) {
  const SolverBody &a = solverBodies_[manifold.a], &b = solverBodies_[manifold.b];
  std::pair<Vec3, Vec3> fixedA = startVelocities_[manifold.a], fixedB = startVelocities_[manifold.b];
  auto& [linearA, angularA] = a.movable ? impactVelocities_[manifold.a] : fixedA;
  auto& [linearB, angularB] = b.movable ? impactVelocities_[manifold.b] : fixedB;
  Eigen::Vector4d error = Eigen::Vector4d::Zero();
  int mask = 0;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const PointConstraint& c = contact.rows[p];
    const double speed = (linearB - linearA).dot(manifold.normal) + angularB.dot(c.crossB[0]) - angularA.dot(c.crossA[0]);
    if (!(speed < -still)) continue;
    const bool bounces = -speed > settings_.restitutionThreshold;
    error[p] = speed - (bounces ? -contact.restitution * speed : 0.0);
    mask |= 1 << p;
  }
  if (mask == 0) return false;
  const Eigen::Vector4d change = bounceImpulses(contact.mass, error, total, manifold.pointCount, mask);
  for (int p = 0; p < manifold.pointCount; ++p) {
    const double impulse = std::max(total[p] + change[p], 0.0) - total[p];
    total[p] += impulse;
    const PointConstraint& c = contact.rows[p];
    if (a.movable) {
      linearA -= (c.inverseMassA * impulse) * manifold.normal.cwiseProduct(a.linearMask);
      angularA -= impulse * c.turnA[0];
    }
    if (b.movable) {
      linearB += (c.inverseMassB * impulse) * manifold.normal.cwiseProduct(b.linearMask);
      angularB += impulse * c.turnB[0];
    }
  }
  return true;
}

double SequentialImpulseSolver::largestPenetration(const std::vector<ContactManifold>& manifolds,
                                                   const ContactIsland& island) const {
  double deepest = 0.0;
  for (std::uint32_t m : island.manifolds) {
    double gaps[ContactManifold::maxPoints];
    manifoldGaps(manifolds[m], gaps);
    for (int p = 0; p < manifolds[m].pointCount; ++p) deepest = std::max(deepest, -gaps[p]);
  }
  return deepest;
}

}  // namespace physdbg
