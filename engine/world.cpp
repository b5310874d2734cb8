#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/baselines/static_pairs.h"
#include "engine/baselines/brute_force_broad_phase.h"
#include "engine/broadphase/tree_broad_phase.h"
#include "engine/parallel/task_system.h"
#include "engine/stage_timer.h"

namespace physdbg {
namespace {

constexpr std::size_t bodyGrain = 256;  // a body's prediction is ~0.1 us (contact_pass.cpp's grains)

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

// The design's both-orders baseline tests every pair twice on purpose, so it
// takes no answer again.
ContactPassSettings contactPassSettings(const WorldSettings& settings) {
  return {settings.narrowPhase, settings.bruteForceBothOrders,
          settings.reuseContacts && !settings.bruteForceBothOrders, settings.castFastPairs};
}

}  // namespace

World::World(const WorldSettings& settings, std::shared_ptr<CollisionOffload> offload)
    : settings_(settings),
      tasks_(std::make_unique<TaskSystem>(settings.threads)),
      offload_(std::move(offload)),
      broadPhase_(makeBroadPhase(settings, *tasks_, offload_.get())),
      contactPass_(contactPassSettings(settings), offload_.get()),
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

int World::threadCount() const { return tasks_->threadCount(); }

const DynamicAabbTree* World::tree() const {
  const auto* tree = dynamic_cast<const TreeBroadPhase*>(broadPhase_.get());
  return tree ? &tree->tree() : nullptr;
}

// The order of a step, as the design describes it. When velocities are
// integrated differs by solver: the seed solver integrates them in beginStep
// (the design's order), sequential impulses inside its substeps. Each stage
// visits the active bodies and their pairs only (world_bodies.cpp).
void World::step() {
  stats_ = StepStats{};
  StepProfile& profile = stats_.profile;
  const StageTimer whole(profile.total);
  const StepContext context{settings_.dt, settings_.gravity, tasks_.get()};
  {
    const StageTimer timer(profile.forces);
    applyForces();  // scheduled states and forces, wakes, gravity (world_bodies.cpp)
    solver_->beginStep(bodies_, refreshMoving(), context);
    freezeNonFiniteBodies();
  }
  {
    const StageTimer timer(profile.broadPhase);
    updateBroadPhase(context);  // fat boxes follow the bodies that moved
  }
  findContacts(context);  // candidate pairs, then the narrow phase (narrowphase/contact_pass.h)
  // A body woken by a touch had no pairs with what else it rests on (asleep,
  // its proxy made none): find them before solving, or it would fall a step.
  while (wakeTouchedBodies(context)) findContacts(context);
  // After the last pass: a second pass must find what the first found (the
  // last step's answers), or a wake would change pairs it never touched.
  contactPass_.keepAnswers(bodies_, solver_->manifolds());
  solveContacts(context);  // responses, then positions
  const StageTimer timer(profile.afterSolve);
  moveKinematicBodies(context);
  const std::vector<Contact>& contacts = contactPass_.contacts();
  events_.update(solver_->eventContacts(contacts), [this](const BodyPair& pair) { return atRest(pair); },
                 restChanged_, listener_);
  if (keepHistory_) history_.add(solver_->touchedPoints(contacts));
  islands_.link(contacts, movable_);
  keepRestingContacts(fallAsleep(context));  // sleep/sleep_islands.h
  freezeNonFiniteBodies();
  applyLifetimes(stepCount_ + 1);  // the state this step ends in has the bodies it should
  restChanged_ = false;
  ++stepCount_;
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
    if (filtersInUse_)
      stats_.filteredPairs += static_cast<int>(std::erase_if(pairs_, [this](const BodyPair& pair) {
        return !bodies_[pair.a].filter().allows(bodies_[pair.b].filter());
      }));
  }
  stats_.broadPhase = broadPhase_->stats();
  stats_.candidatePairs = static_cast<int>(pairs_.size());
  ContactPassCounts counts;
  contactPass_.run(bodies_, pairs_, [this](BodyId id) { return isMoving(id); }, *solver_, context, profile, counts);
  stats_.boundsRejected += counts.boundsRejected;
  stats_.manifoldPoints += counts.manifoldPoints;
  stats_.narrowPhase += counts.narrowPhase;
  stats_.manifolds = static_cast<int>(solver_->manifolds().size());
  if (!settings_.skipStaticPairs) {
    const StageTimer timer(profile.narrowPhase);
    const StaticPairCounts statics = testStaticPairs(bodies_, present_, *tasks_, settings_.narrowPhase);
    stats_.staticPairsTested += statics.tested;
    stats_.narrowPhase += statics.narrowPhase;
  }
  stats_.contacts = static_cast<int>(contactPass_.contacts().size());
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
  for (const Contact& contact : contactPass_.contacts()) {
    wakeIfTouched(contact.a, contact.b, true);
    wakeIfTouched(contact.b, contact.a, true);
  }
  for (const ContactManifold& manifold : solver_->manifolds()) {
    if (asleep_[manifold.a] == asleep_[manifold.b]) continue;
    const BodyId sleeper = asleep_[manifold.a] ? manifold.a : manifold.b;
    const BodyId other = sleeper == manifold.a ? manifold.b : manifold.a;
    if (asleep_[sleeper] && isMoving(other))
      wakeIfTouched(sleeper, other,
                    closesOnSleeper(manifold, bodies_[other], other == manifold.a, context.dt, solver_->touchingGap()));
  }
  return woke;
}

void World::solveContacts(const StepContext& context) {
  SolverStepReport report;
  {
    const StageTimer timer(stats_.profile.solver);
    report = solver_->solve(bodies_, refreshMoving(), contactPass_.contacts(), context);
  }
  stats_.profile.solverIslands = report.islandSeconds;
  stats_.responses = report.responses;
  stats_.largestPenetration = report.largestPenetration;
  stats_.substeps = report.substeps;
  stats_.contactHertz = report.contactHertz;
}

// An island fell asleep together, so it wakes together: a body left asleep
// beside a woken neighbour would hold no contacts with it (sleeping proxies
// make no pairs) until the next touch woke it a step late.
void World::wake(BodyId id) {
  if (!asleep_[requireLive(id)]) return;
  const BodyId island = islands_.label(id);
  const std::vector<BodyId> members = islands_.takeIsland(island);
  if (members.empty()) wakeBody(id);  // asleep alone
  // A member that woke, left or fell asleep in another island since is no
  // longer this island's.
  for (const BodyId member : members)
    if (asleep_[member] && islands_.label(member) == island) wakeBody(member);
}

void World::sleep(BodyId id) {
  requireLive(id);
  if (!bodies_[id].isDynamic())
    throw std::invalid_argument("body " + std::to_string(id) + " is static or kinematic: only a dynamic body sleeps");
  if (!takesPart(id))
    throw std::invalid_argument("body " + std::to_string(id) + " is absent or frozen: it cannot sleep");
  if (asleep_[id]) return;
  islands_.makeAlone(id);  // waking it wakes no other body
  putToSleep(id);
}

bool World::fallAsleep(const StepContext& context) {
  const SleepSettings sleep{settings_.allowSleep, settings_.sleepLinearSpeed, settings_.sleepAngularSpeed,
                            settings_.timeToSleep};
  islands_.findSleepers(bodies_, movable_, sleep, context.dt, sleepers_);
  for (const Sleeper& sleeper : sleepers_) putToSleep(sleeper.body);
  return !sleepers_.empty();
}

void World::scheduleForce(const ScheduledForce& force) {
  checkScheduledForce(force, bodies_);
  requireLive(force.body);
  scheduledForces_.push_back(force);
}

void World::scheduleState(const ScheduledState& state) {
  checkScheduledState(state, bodies_, stepCount_);
  requireLive(state.body);
  scheduledStates_.push_back(state);
}

void World::scheduleLifetime(const BodyLifetime& lifetime) {
  checkLifetime(lifetime, lifetimes_, bodies_, stepCount_);
  requireLive(lifetime.body);
  lifetimes_.push_back(lifetime);
  if (lifetime.addAtStep > stepCount_) removeBody(lifetime.body);
}

// Removals first, in the order scheduled, so a body leaving and one arriving
// on the same step never meet.
void World::applyLifetimes(int state) {
  for (const BodyLifetime& lifetime : lifetimes_)
    if (lifetime.removeAtStep == state) removeBody(lifetime.body);
  for (const BodyLifetime& lifetime : lifetimes_)
    if (lifetime.addAtStep == state) restoreBody(lifetime.body);
}

std::size_t World::touchingPairCount() const { return events_.touchingPairs().size(); }

}  // namespace physdbg
