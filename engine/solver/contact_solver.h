#pragma once
// The contact solver behind World. World::step is one unbranched pipeline
// (forces, broad phase, narrow phase, solver, events, sleep); whatever
// differs between solvers is asked of the solver: whether velocities are
// integrated before the narrow phase or inside the solve, how far ahead a
// body's proxy box reaches, how far apart a pair still matters, what counts
// as touching, what it keeps between steps (warm starting) and which points
// the debugger shows. makeContactSolver is the one place that picks one.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/aabb.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_history.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/solver/movable_bodies.h"
#include "engine/solver/solver_settings.h"
#include "engine/solver/step_context.h"

namespace physdbg {

struct NarrowPhaseOptions;
struct ReusableContact;

// Where a candidate's manifold comes from when the solver need not build it:
// `built` by a collision offload (collision_offload.h), else `kept`, the last
// answer taken again (contact_reuse.h), carried to the bodies' poses straight
// into the solver's own slot. Both null: the solver builds it.
struct ManifoldSource {
  const ContactManifold* built = nullptr;
  const ReusableContact* kept = nullptr;
};

// Where a moving body's broad-phase box goes this step, and the displacement
// the tree uses to stretch its fat box ahead of the motion.
struct PredictedMotion {
  Aabb box;
  Vec3 displacement = Vec3::Zero();
};

struct SolverStepReport {
  int responses = 0;                // contacts (seed) or manifolds (sequential impulses) solved
  double largestPenetration = 0.0;  // left after the step, m (sequential impulses)
  int substeps = 0;                 // the most any island took this step
  double contactHertz = 0.0;        // the stiffest contact frequency any island used
  double islandSeconds = 0.0;       // wall time spent solving islands, the rest being set-up
};

// One body's share of a pair's contact reach (ContactSolver::bodyReach).
struct BodyReach {
  Vec3 linearVelocity = Vec3::Zero();  // m/s
  double acceleration = 0.0;           // m/s^2, this step's
  double spin = 0.0;                   // m/s: angular speed times the body's bounding radius
};

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;

  // Called after forces were applied, before the broad phase.
  virtual void beginStep(std::vector<RigidBody>& bodies, const MovableBodies& movable, const StepContext& step) = 0;
  virtual PredictedMotion predictMotion(const RigidBody& body, const StepContext& step) const = 0;
  // How far apart two surfaces may be and still be handed to addCandidate.
  // It comes from what each body alone contributes (bodyReach), which World
  // finds once per body and pass: a body meets many candidate pairs.
  virtual BodyReach bodyReach(const RigidBody& body, const StepContext& step) const = 0;
  virtual double contactReach(const BodyReach& a, const BodyReach& b, const StepContext& step) const = 0;
  // At least what one body adds to any pair's reach, so that, in exact
  // arithmetic, contactReach(a, b) <= reachShare(a) + reachShare(b). World
  // grows each body's box by its share once per pass: a pair whose grown
  // boxes miss is out of reach without its own reach being worked out.
  virtual double reachShare(const BodyReach& body, const StepContext& step) const = 0;
  double contactReach(const RigidBody& a, const RigidBody& b, const StepContext& step) const {
    return contactReach(bodyReach(a, step), bodyReach(b, step), step);
  }
  // Surfaces this close count as touching: contact events, red boxes, islands.
  virtual double touchingGap() const = 0;

  // A new narrow-phase pass begins (World may run several in a step when a
  // touch wakes a body).
  virtual void clearContacts() = 0;
  // Every narrow-phase result within reach, in pair order. Returns the
  // manifold points it kept (0 for a solver without manifolds).
  virtual int addCandidate(const Contact& contact, const RigidBody& a, const RigidBody& b, double reach) = 0;
  // A whole pass's candidates at once, in pair order, `reaches[i]` being
  // candidates[i]'s contactReach: keeps what addCandidate on each in turn
  // would, which is what this default does. A solver may spread the work over
  // step.tasks as long as the result does not depend on how it is split.
  // `sources` is empty, or holds per candidate where its manifold comes
  // from (ManifoldSource); a solver with manifolds uses those instead of
  // building its own.
  virtual int addCandidates(const std::vector<Contact>& candidates, const std::vector<double>& reaches,
                            const std::vector<RigidBody>& bodies, const StepContext& step,
                            const std::vector<ManifoldSource>& sources);

  // Solves `contacts` (the touching ones) or the kept candidates, and moves
  // every movable body to the end of the step.
  virtual SolverStepReport solve(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                 const std::vector<Contact>& contacts, const StepContext& step) = 0;

  // The pairs contact events report as touching, in pair order: `contacts`,
  // plus whatever else the solver pushed on.
  virtual const std::vector<Contact>& eventContacts(const std::vector<Contact>& contacts) = 0;
  // This step's touched points, for the debugger (contact_history.h).
  virtual std::vector<ShownContact> touchedPoints(const std::vector<Contact>& contacts) const = 0;
  // This step's manifolds, speculative points included; empty without manifolds.
  virtual const std::vector<ContactManifold>& manifolds() const = 0;
};

std::unique_ptr<ContactSolver> makeContactSolver(const SolverSettings& settings,
                                                 const NarrowPhaseOptions& narrowPhase);

}  // namespace physdbg
