#pragma once
// The world owns the bodies and advances them. World::step() is the one place
// that shows the order of a step; each stage lives in its own folder
// (broadphase/, narrowphase/, contacts/, solver/), and what differs between
// solvers is asked of the ContactSolver (solver/contact_solver.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/broadphase/tree_options.h"
#include "engine/collision_offload.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_events.h"
#include "engine/contacts/contact_history.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/active_bodies.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/dynamics/step_schedule.h"
#include "engine/world_settings.h"
#include "engine/math.h"
#include "engine/narrowphase/contact_pass.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/sleep/sleep_islands.h"
#include "engine/solver/contact_solver.h"
#include "engine/solver/solver_settings.h"
#include "engine/step_profile.h"

namespace physdbg {

class DynamicAabbTree;
class TaskSystem;

// A body whose state stopped being finite: reported once, then frozen.
struct NumericalFault {
  BodyId body = 0;
  int step = 0;
  std::string what;
};

class World {
 public:
  // Throws std::invalid_argument when settings.collisionDevice is Gpu and no
  // offload is given, or an offload is given for a Cpu world.
  explicit World(const WorldSettings& settings = {}, std::shared_ptr<CollisionOffload> offload = nullptr);
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // Throws std::invalid_argument (see RigidBody) for a bad definition.
  BodyId addBody(const BodyDefinition& definition);
  // Room for `count` bodies in all, so a loader that knows its count builds
  // the world without growing the per-body tables past it.
  void reserveBodies(std::size_t count);

  std::size_t bodyCount() const { return bodies_.size(); }
  // What is changed through this reference reaches the next step: a sleeping
  // body given a velocity or a force wakes, one made non-finite is frozen.
  // (The step visits only awake bodies and the bodies handed out here.)
  RigidBody& body(BodyId id);
  const RigidBody& body(BodyId id) const { return bodies_[requireLive(id)]; }
  const std::vector<RigidBody>& bodies() const { return bodies_; }

  const WorldSettings& settings() const { return settings_; }
  // The threads a step uses: settings().threads, or the machine's for 0.
  int threadCount() const;
  int stepCount() const { return stepCount_; }
  double time() const { return stepCount_ * settings_.dt; }

  void step();

  // Throws std::invalid_argument for an unknown, static or kinematic body, a
  // torque with a point, non-finite vectors or an empty step range.
  void scheduleForce(const ScheduledForce& force);
  // Throws std::invalid_argument for an unknown or static body, nothing to
  // set, non-finite values, a zero orientation or a step the run has passed.
  // Changes scheduled for the same step apply in the order scheduled.
  void scheduleState(const ScheduledState& state);

  // Takes the body out of the run, keeping its id and state: its proxy leaves
  // the broad phase, its touching pairs end now (`end` events), the bodies
  // it touched wake, and nothing moves, pushes or draws it until restoreBody.
  void removeBody(BodyId id);
  // Puts a removed body back, awake, where and as fast as it was.
  void restoreBody(BodyId id);
  bool isPresent(BodyId id) const { return present_.at(id); }
  // Takes the body out for good (as removeBody, and its lifetime is
  // dropped). Ids are never handed out again, so a stale id cannot name
  // another body: every later call that acts on or hands out this one
  // (body, sleep, wake, schedule*, removeBody, restoreBody, destroyBody)
  // throws std::invalid_argument saying it was destroyed.
  void destroyBody(BodyId id);
  bool isDestroyed(BodyId id) const { return destroyed_.at(id); }
  // Removes the body now if it comes later, and applies the lifetime's steps
  // as the run reaches them. Throws std::invalid_argument for an unknown
  // body, a second lifetime for it, a negative addAtStep, removeAtStep <=
  // addAtStep or a step the run has passed.
  void scheduleLifetime(const BodyLifetime& lifetime);

  // Not owned; may be null. Receives begin/stay/end after each step.
  void setContactListener(ContactListener* listener) { listener_ = listener; }

  bool isAsleep(BodyId id) const { return asleep_.at(id); }
  // Puts a dynamic body to sleep now, before the first step or between
  // steps, alone in its island and with its velocities zeroed: it stays where
  // it is, untouched by gravity, until something wakes it as any sleeping
  // body (a moving body's touch, a force, a velocity, a scheduled state,
  // wake()). Throws std::invalid_argument for an unknown, static, kinematic,
  // absent or frozen body.
  void sleep(BodyId id);
  // Wakes the body and every body of the island it fell asleep with.
  void wake(BodyId id);
  // The lowest id of the body's island: awake bodies linked by the last
  // step's touching contacts, or, for a sleeping body, the island it fell
  // asleep with. A static or frozen body is alone (its own id).
  BodyId islandOf(BodyId id) const { return islands_.label(id); }
  bool isFrozen(BodyId id) const { return frozen_.at(id); }
  const std::vector<NumericalFault>& numericalFaults() const { return faults_; }
  const StepStats& lastStepStats() const { return stats_; }
  const std::vector<Contact>& contacts() const { return contactPass_.contacts(); }
  // The triangles of meshes and heightfields the last step's narrow phase
  // tested, and where it gave a contact the face normal (the mesh layer).
  const std::vector<ContactPass::MeshTest>& meshTests() const { return contactPass_.meshTests(); }
  // Pairs touching after the last step, asleep ones included: the pairs
  // contact events hold as begun and not ended. contacts() has the awake ones.
  std::size_t touchingPairCount() const;
  // Sequential-impulse solver only: this step's manifolds, speculative points included.
  const std::vector<ContactManifold>& manifolds() const { return solver_->manifolds(); }
  const std::vector<BodyPair>& candidatePairs() const { return pairs_; }
  // The broad-phase tree, or null when the brute-force broad phase is used.
  const DynamicAabbTree* tree() const;

  // Display only, nothing here changes a step. With the history kept, every
  // step's touched points stay until clearContactHistory(), so a frame that
  // spans several steps shows them all (the debugger keeps it, frame by frame).
  void keepContactHistory(bool keep) {
    keepHistory_ = keep;
    history_.clear();
  }
  void clearContactHistory() { history_.clear(); }
  // What the contacts and aabbs layers show, sorted by pair and feature:
  // before the first step, the initial state's touching points (found here,
  // nothing is stepped); after it, the history (without one, the last step's
  // touched points), plus the points sleeping bodies rest on, marked resting.
  std::vector<ShownContact> shownContacts() const;

  // What the debugger reads (engine/debug/world_debug_draw.h): the body's
  // broad-phase proxy (-1 once frozen or removed) and its fat box, and the
  // points sleeping bodies rest on.
  int proxyOf(BodyId id) const { return proxies_.at(id); }
  const Aabb& fatBox(BodyId id) const;
  const std::vector<ShownContact>& restingContacts() const { return resting_; }

 private:
  // The step's stages, in world.cpp in step order; the per-body ones in
  // world_bodies.cpp; the contacts the debugger shows in
  // world_shown_contacts.cpp (drawn by engine/debug/world_debug_draw.h).
  void applyForces();
  void applyScheduledForces();
  void applyScheduledStates();
  void wakePushedBodies();
  void moveKinematicBodies(const StepContext& context);
  void updateBroadPhase(const StepContext& context);
  void findContacts(const StepContext& context);
  bool wakeTouchedBodies(const StepContext& context);  // true when a body woke
  void solveContacts(const StepContext& context);
  bool fallAsleep(const StepContext& context);  // true when an island fell asleep
  void keepRestingContacts(bool fellAsleep);
  void freezeNonFiniteBodies();  // the active bodies and the edited ones
  void applyLifetimes(int state);  // add and remove what the lifetimes say for `state`

  // A body's state: active_ follows it (present, finite, not static, not asleep).
  void updateActivity(BodyId id);
  // moving_ and movable_ from the active bodies, as isMoving says now.
  const MovableBodies& refreshMoving();
  void putToSleep(BodyId id);
  void setAsleep(BodyId id, bool asleep);  // the flag and the count of sleepers
  void wakeBody(BodyId id);  // this body only; wake() wakes its island
  // Moves this step: a dynamic body awake and finite, or a kinematic body
  // with a velocity (a still one is as good as static).
  bool isMoving(BodyId id) const;
  // Present and finite: the body is in the broad phase and can touch.
  bool takesPart(BodyId id) const { return present_[id] && !frozen_[id]; }
  // The id names a body that was not destroyed; returns it, else throws.
  BodyId requireLive(BodyId id) const;
  // Both bodies take part and do not move, and one sleeps: the pair touches
  // silently (contact events, the points sleeping bodies rest on).
  bool atRest(const BodyPair& pair) const;

  std::vector<ShownContact> initialContacts() const;
  std::vector<BodyPair> overlappingBoxes(double margin) const;

  WorldSettings settings_;
  // Bodies, and their state by kind: one store each.
  std::vector<RigidBody> bodies_;
  std::vector<int> proxies_;  // broad-phase proxy per body, -1 once frozen or removed
  std::vector<bool> frozen_, asleep_, present_, destroyed_;
  int sleepingCount_ = 0;        // present, finite sleeping bodies
  ActiveBodies active_;          // the bodies a step visits
  std::vector<BodyId> moving_;   // active bodies that move this step, ascending (refreshMoving)
  MovableBodies movable_;        // the dynamic ones among them (refreshMoving)
  std::vector<BodyId> edited_;   // handed out by body(id) since the last step
  std::vector<char> isEdited_;   // per body: in edited_
  SleepIslands islands_;         // islands, slow times and the sleeping islands' members
  std::vector<Sleeper> sleepers_;  // this step's (fallAsleep)
  // A body woke, left, froze or a kinematic body's motion was set since the
  // last step ended: pairs at rest may no longer be.
  bool restChanged_ = false;

  std::unique_ptr<TaskSystem> tasks_;  // before broadPhase_, which may hold a pointer to it
  std::shared_ptr<CollisionOffload> offload_;  // before broadPhase_, which it may have made
  std::unique_ptr<BroadPhase> broadPhase_;
  std::vector<BodyPair> pairs_;
  std::vector<PredictedMotion> predictions_;  // per moving body, this step (updateBroadPhase)
  ContactPass contactPass_;
  std::unique_ptr<ContactSolver> solver_;
  ContactEventTracker events_;
  ContactHistory history_;
  bool keepHistory_ = false;
  bool filtersInUse_ = false;  // a body was added with a collision filter other than the default
  std::vector<ShownContact> resting_;  // sorted; what sleeping bodies rest on
  ContactListener* listener_ = nullptr;
  std::vector<ScheduledForce> scheduledForces_;
  std::vector<ScheduledState> scheduledStates_;
  std::vector<BodyLifetime> lifetimes_;
  std::vector<NumericalFault> faults_;
  StepStats stats_;
  int stepCount_ = 0;
};

}  // namespace physdbg
