#pragma once
// Sequential impulses over contact manifolds with soft contacts and substeps
// (the "soft step" scheme of Box2D v3, written from its description): each
// substep integrates velocities, warm-starts and solves every contact point
// (normal with a soft push-out of penetration, Coulomb friction clamped by the
// normal impulse), integrates positions, then relaxes the contacts without
// the push so it leaves no velocity behind. Restitution is applied once at
// the end. Speculative points (still apart) let a body close exactly its gap:
// no tunnelling, and no energy from position correction.
//
// Mass ratios: a soft contact's stiffness follows its effective mass, so a
// light body under a heavy one would sink far (resting_load.h). Each step
// finds the weight every contact holds (for one that holds none up, the force
// it carried last step), stiffens the contacts (and takes
// more substeps) until the most loaded one settles within restingOverlap,
// and starts new contacts at their load. This is decided per island
// (contact_islands.h), so only the pile that needs it pays for it.
//
// Order and threads: islands that take the same substeps are solved as one
// batch, up to about a hundred manifolds (a thousand boxes resting alone on
// the floor make a few batches, which threads solve side by side), whose
// manifolds are coloured (constraint_colouring.h) so that a colour's
// manifolds share no movable body. Sweeps go colour by colour, solving a
// colour's manifolds side by side in SIMD lanes (wide_contact_rows.h) and
// over the world's threads, then the few that fit no colour one by one.
// Batches run in parallel too (an island touching a kinematic body, which it
// moves through its own substeps, is a batch of its own; those take turns).
// Each batch builds its own constraint rows once it knows its groups,
// straight into the lanes (sequential_impulse_prepare.cpp). Nothing depends
// on how work is split: any thread count gives the same result bit for bit.
#include <algorithm>
#include <span>
#include <vector>

#include "engine/contacts/manifold_builder.h"
#include "engine/parallel/task_system.h"
#include "engine/solver/body_ranks.h"
#include "engine/solver/contact_islands.h"
#include "engine/solver/contact_solver.h"
#include "engine/solver/point_constraint.h"
#include "engine/solver/solver_body.h"
#include "engine/solver/warm_start_memory.h"
#include "engine/solver/wide_contact_rows.h"
#include "engine/solver/wide_group_pool.h"

namespace physdbg {

class SequentialImpulseSolver final : public ContactSolver {
 public:
  explicit SequentialImpulseSolver(const SolverSettings& settings) : settings_(settings) {}

  // Last step's manifolds become the warm-start source here, once per step:
  // a second narrow-phase pass (a touch woke a body) must not lose them.
  void beginStep(std::vector<RigidBody>&, const MovableBodies&, const StepContext&) override;
  PredictedMotion predictMotion(const RigidBody& body, const StepContext& step) const override;
  BodyReach bodyReach(const RigidBody& body, const StepContext& step) const override;
  double contactReach(const BodyReach& a, const BodyReach& b, const StepContext& step) const override;
  double reachShare(const BodyReach& body, const StepContext& step) const override;
  using ContactSolver::contactReach;
  double touchingGap() const override { return settings_.linearSlop; }
  void clearContacts() override;
  int addCandidate(const Contact& contact, const RigidBody& a, const RigidBody& b, double reach) override;
  // Builds the manifolds in parallel, one slot per candidate and a scratch
  // per piece, then keeps them in pair order (sequential_impulse_candidates.cpp).
  int addCandidates(const std::vector<Contact>& candidates, const std::vector<double>& reaches,
                    const std::vector<RigidBody>& bodies, const StepContext& step,
                    const std::vector<ManifoldSource>& sources) override;
  SolverStepReport solve(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                         const std::vector<Contact>& contacts, const StepContext& step) override;
  const std::vector<Contact>& eventContacts(const std::vector<Contact>& contacts) override;
  std::vector<ShownContact> touchedPoints(const std::vector<Contact>& contacts) const override;
  const std::vector<ContactManifold>& manifolds() const override { return manifolds_; }

 private:
  // Advances every movable body by dt (velocities and positions) while
  // solving the manifolds. `movable[i]` false: body i is immovable this step
  // (static, asleep or frozen). Impulses in the manifolds warm-start the solve
  // and hold the final ones afterwards (those of the island's last substep);
  // each point's stepNormalImpulse holds the step's total. Gravity tells which
  // contacts hold weight (resting_load.h).
  SolverStepReport solveManifolds(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                  std::vector<ContactManifold>& manifolds, const StepContext& step);

  // One batch of islands' work this step (islands with the same substeps
  // are solved together, batchIslands): its substeps, its colours (each a list of
  // wide groups plus the manifolds solved one by one: the speculative ones
  // solved all points together, or all of them with wideContacts off) and
  // the overflow, solved one by one after the colours.
  struct ColourWork {
    std::size_t firstGroup = 0, groupCount = 0;  // in IslandWork::groups
    std::vector<std::uint32_t> scalar;
  };
  // Kept from step to step (batches_), so each batch's lists reuse their
  // storage. Its groups and slots are borrowed from groupPool_ while it runs.
  struct IslandWork {
    std::vector<std::uint32_t> manifolds, bodies;  // its islands' together, ascending
    ContactIsland island() const { return {manifolds, bodies}; }
    SubstepContext substeps;
    std::vector<ColourWork> colours;
    std::vector<std::uint32_t> overflow;
    WideGroups groups;
    WideSlots slots;  // the groups' point slots
    std::vector<std::uint32_t> singles;  // every manifold in no group: the colours' scalar ones and the overflow
    bool touchesKinematic = false;
    double largestPenetration = 0.0;
  };

  // The two ways an island is calm (SolverSettings::calmSubsteps).
  bool restsAlone(const std::vector<ContactManifold>& manifolds, const ContactIsland& island) const;
  double normalSpeed(const ContactManifold& manifold) const;
  bool restsTogether(const std::vector<ContactManifold>& manifolds, const ContactIsland& island) const;
  // calm: the island starts from SolverSettings::calmSubsteps.
  SubstepContext chooseSubsteps(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds,
                                const ContactIsland& island, const std::vector<double>& loads, double gravity,
                                const StepContext& step, bool calm) const;
  // Exact above `enough`; at or below it, any value up to `enough`.
  double loadedHertz(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds,
                     const ContactIsland& island, const std::vector<double>& loads, double gravity,
                     double enough) const;
  double manifoldDemand(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds,
                        std::uint32_t m, const std::vector<double>& loads, double gravity, bool bound) const;
  double carriedForce(const ContactManifold& manifold) const;
  double bodySize(const ContactManifold& manifold) const;
  void rescaleWarmStart(std::vector<ContactManifold>& manifolds, const ContactIsland& island,
                        const std::vector<bool>& movable, double substep) const;
  SubstepContext flightSubsteps(const StepContext& step) const;
  // Movable bodies that no batch holds (inBatch_ unset).
  void integrateFreeBodies(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                           const SubstepContext& substeps);
  // Into batches_, whose first batchCount_ entries are this step's.
  void batchIslands(const ContactIslands& islands, const std::vector<SubstepContext>& substeps,
                    const std::vector<char>& kinematic);
  void runBatch(std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
                std::vector<ContactManifold>& manifolds, IslandWork& work);
  void planIsland(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                  const std::vector<bool>& movable, IslandWork& work);
  // `kinematic`: the kinematic bodies the batch touches (kinematicNeighbours).
  void solveIsland(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds, IslandWork& work,
                   const std::vector<std::uint32_t>& kinematic);
  // body(i) for i in [0, count), spread over the world's threads when there
  // is enough work; each i must write only what it owns.
  // Templates, not std::function: a substep calls them per body and per
  // group, and the indirect call per element was measurable.
  template <class Body>
  void forEach(std::size_t count, std::size_t grain, const Body& body) const {
    if (!tasks_ || tasks_->threadCount() <= 1 || count <= grain) {
      for (std::size_t i = 0; i < count; ++i) body(i);
      return;
    }
    tasks_->parallelFor(count, grain, [&body](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) body(i);
    });
  }
  // Each colour's wide groups and single manifolds (in parallel), then the overflow.
  template <class Wide, class Single>
  void runColours(IslandWork& work, const Wide& wide, const Single& single) const {
    // A piece of a colour should outweigh handing it to another thread.
    // Wide groups go four at a time (solveWide), the bundles fixed by index.
    constexpr std::size_t grain = 32, bundle = 4;
    for (const ColourWork& colour : work.colours) {
      const std::size_t bundles = (colour.groupCount + bundle - 1) / bundle;
      forEach(bundles + colour.scalar.size(), grain, [&](std::size_t i) {
        if (i < bundles) {
          const std::size_t first = bundle * i;
          wide(std::span<WideManifolds>(work.groups.data() + colour.firstGroup + first,
                                        std::min(bundle, colour.groupCount - first)));
        } else {
          single(colour.scalar[i - bundles]);
        }
      });
    }
    for (std::uint32_t m : work.overflow) single(m);
  }
  void prepare(const std::vector<RigidBody>& bodies, const std::vector<bool>& movable,
               std::vector<ContactManifold>& manifolds, double dt);
  // Calm time of a body listed this solve: it restarts when the body was not
  // listed in the one before (it was in flight, asleep or static meanwhile).
  void updateCalmTime(std::uint32_t id, double dt);
  // Per manifold, the factors on a's and b's inverse mass and inertia: 1,
  // except where a heavy body rests on a much lighter one (massRatioLimit).
  std::vector<std::pair<double, double>> supportMassScales(const std::vector<ContactManifold>& manifolds) const;
  void integrateVelocities(const ContactIsland& island, double h);
  void integratePositions(std::span<const std::uint32_t> ids, double h);
  std::vector<std::uint32_t> kinematicNeighbours(const std::vector<RigidBody>& bodies,
                                                 const std::vector<ContactManifold>& manifolds,
                                                 const ContactIsland& island);
  void measureGaps(const std::vector<ContactManifold>& manifolds, IslandWork& work);
  void warmStart(std::vector<ContactManifold>& manifolds, IslandWork& work);
  void warmStartManifold(ContactManifold& manifold, std::size_t m);
  // Constraint rows (sequential_impulse_prepare.cpp): what a manifold's
  // points share, each point's rows [0, rows) into out[0, pointCount), and
  // a batch's constraints (wideMembers[groupStarts[g], groupStarts[g + 1])
  // are group g's manifolds).
  ManifoldFrame manifoldFrame(const std::vector<RigidBody>& bodies, const ContactManifold& manifold, std::size_t m,
                              bool withMotion) const;
  ConstraintSettings constraintSettings() const;
  // Manifold m's point constraints (prepare sizes them).
  PointConstraint* pointConstraints(std::size_t m) { return constraints_.data() + constraintStart_[m]; }
  const PointConstraint* pointConstraints(std::size_t m) const { return constraints_.data() + constraintStart_[m]; }
  void buildNormalRows(const std::vector<RigidBody>& bodies, const ContactManifold& manifold, std::size_t m, int rows,
                       PointConstraint* out) const;
  // Either body has a translation lock: its manifolds are solved one by one,
  // with masked linear rows (maskLinearRows).
  bool hasLinearLocks(const ContactManifold& manifold) const;
  void buildBatchConstraints(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                             IslandWork& work, const std::vector<std::uint32_t>& wideMembers,
                             const std::vector<std::size_t>& groupStarts);
  void prepareApproaches(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds,
                         const Vec3& gravity, double dt);
  // useBias: the soft push-out of overlap (off in the relax pass after positions moved).
  void solveNormals(ContactManifold& manifold, std::size_t m, const SubstepContext& substeps, bool useBias,
                    bool reversed);
  bool solveApproachTogether(ContactManifold& manifold, std::size_t m, double substep);
  bool solveOverlapTogether(ContactManifold& manifold, std::size_t m, const SubstepContext& substeps, bool useBias);
  void solveFriction(ContactManifold& manifold, std::size_t m, bool reversed);
  // stepEnds: the relax sweep after the step's last move.
  void solve(std::vector<ContactManifold>& manifolds, IslandWork& work, bool useBias, bool reversed,
             bool stepEnds = false);
  bool reachedAny(std::size_t m, int count) const;  // a point's gap within kReachedGap
  // After the substeps, manifold by manifold (bounce.h), or passed on from
  // contact to contact where an impact travels through touching bodies.
  void applyRestitution(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                        const ContactIsland& island, double substep, double dt);
  bool mayBounce(const ContactManifold& manifold, std::size_t m) const;
  // A mask of the points that bounce; `gaps` gets every point's gap (when it may bounce).
  int bouncingPoints(const ContactManifold& manifold, std::size_t m, double (&gaps)[ContactManifold::maxPoints]) const;
  void bounceManifold(ContactManifold& manifold, std::size_t m, double substep);
  // A manifold taking part in the impacts: its normal rows at the start of the step, for passImpactsOn.
  struct ImpactContact {
    std::uint32_t manifold = 0;
    PointConstraint rows[ContactManifold::maxPoints];
    Eigen::Matrix4d mass;
    double restitution = 0.0;
  };
  bool takesPartInImpacts(const ContactManifold& manifold) const;
  bool passesImpactsOn(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds,
                       const ContactIsland& island) const;
  void passImpactsOn(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                     const ContactIsland& island, double dt);
  std::vector<Eigen::Vector4d> sequentialImpacts(const std::vector<ContactManifold>& manifolds,
                                                 const std::vector<ImpactContact>& contacts, double dt);
  bool impactOnce(const ContactManifold& manifold, const ImpactContact& contact, double still,
                  Eigen::Vector4d& total);
  double closingPull(const ContactManifold& manifold, const PointConstraint& c) const;
  double largestPenetration(const std::vector<ContactManifold>& manifolds, const ContactIsland& island) const;
  // Each point's current gap (separation) at the solver bodies' poses.
  void manifoldGaps(const ContactManifold& manifold, double (&gaps)[ContactManifold::maxPoints]) const;
  double rowVelocity(const ContactManifold& manifold, const PointConstraint& constraint, const Vec3& direction,
                     int row) const;
  void applyRow(const ContactManifold& manifold, const PointConstraint& constraint, const Vec3& direction, int row,
                double impulse);
  void applyNormal(const ContactManifold& manifold, const PointConstraint& constraint, ManifoldPoint& point,
                   double impulse);

  void warmStartFromPreviousStep(const StepContext& step);
  void retireManifolds();  // empties manifolds_, its elements kept in spareManifolds_

  SolverSettings settings_;
  std::vector<ContactManifold> manifolds_;
  WarmStartMemory previousImpulses_;  // the last step's manifolds, as a warm start reads them
  // Manifolds of an earlier pass, left constructed: addCandidates overwrites
  // them in parallel rather than constructing each anew, serially (600 bytes
  // each: 0.8 ms a step for 16000).
  std::vector<ContactManifold> spareManifolds_;
  ManifoldScratch manifoldScratch_;
  std::vector<std::size_t> candidateSlot_;  // per candidate of addCandidates: its manifold, or none
  std::vector<Contact> eventContacts_;  // this step's contacts plus speculative impacts
  BodyRanks ranks_;  // the bodies in this step's manifolds (prepare); the tables below hold those only
  RankedTable<SolverBody> solverBodies_;
  RankedTable<BodyTraits> traits_;  // per body in a manifold, from prepare
  RankedTable<MotionProperties> motionProperties_;  // per body in a manifold, from prepare
  RankedTable<std::pair<Vec3, Vec3>> startVelocities_;  // per body in a manifold: linear, angular at the start
  RankedTable<std::pair<Vec3, Vec3>> impactVelocities_;  // sequentialImpacts' copy
  std::vector<char> listed_;                        // per body: in a manifold this step (prepare)
  std::vector<ManifoldTangents> tangents_;      // per manifold
  // Each point's, manifold m's from constraintStart_[m]; written where
  // constrained_, else left as the allocator gave them.
  std::vector<PointConstraint, DefaultInitialisingAllocator<PointConstraint>> constraints_;
  std::vector<std::size_t> constraintStart_;  // per manifold, and one past the last
  std::vector<char> constrained_;               // per manifold: its constraints are in constraints_
  std::vector<double> touching_;                  // per manifold: largest separation that holds weight, m
  std::vector<char> approaching_;                 // per manifold: every point still apart at the start
  std::vector<char> overlapping_;                 // per manifold: every point deeper than the slop at the start
  std::vector<Eigen::Matrix4d> approachMass_;     // per manifold, where approaching_ or overlapping_: J M^-1 J^T
  std::vector<Eigen::Matrix4d> approachInverse_;  // and its pseudo-inverse
  std::vector<double> lastSubstep_;               // per body: the substep it took last step (0: none yet)
  std::vector<double> calmTime_;                  // per body: s it has begun steps in contact and calm
  std::vector<std::uint64_t> calmSolve_;          // per body: the solve that last listed it (solveCount_)
  std::uint64_t solveCount_ = 0;
  std::vector<std::uint32_t> listedIds_;          // the bodies in a manifold this step, ascending (prepare)
  std::vector<char> inBatch_;                     // per body: in this step's batches (solveManifolds)
  std::vector<std::pair<double, double>> massScales_;  // per manifold, from supportMassScales
  ContactIslands islands_;                             // this step's, from solveManifolds
  std::vector<IslandWork> batches_;                    // [0, batchCount_) this step's
  std::size_t batchCount_ = 0;
  WideGroupPool groupPool_;
  const TaskSystem* tasks_ = nullptr;  // this step's threads (StepContext::tasks)
};

}  // namespace physdbg
