#pragma once
// The design's solver. Its step keeps the design's order: velocities are
// integrated before the narrow phase, every touching contact then gets the
// design's response (CollisionResponseWithRotation) one after another, and
// positions move last. The response, for one contact: skip it when the bodies
// already separate at the contact point, push them apart along the normal in
// proportion to their inverse masses, then apply one impulse through each
// body's contact point that uses both inverse world inertia tensors (locked
// axes taking no part) and the pair's restitution. No friction, no
// manifolds, nothing kept between steps.
#include "engine/solver/contact_solver.h"

namespace physdbg {

// Returns false when the pair was skipped because it already separates.
bool respondToContact(RigidBody& a, RigidBody& b, const ContactResult& contact, const SolverSettings& settings);

class SeedSolver final : public ContactSolver {
 public:
  SeedSolver(const SolverSettings& settings, double touchingTolerance);

  void beginStep(std::vector<RigidBody>& bodies, const MovableBodies& movable, const StepContext& step) override;
  PredictedMotion predictMotion(const RigidBody& body, const StepContext& step) const override;
  BodyReach bodyReach(const RigidBody&, const StepContext&) const override { return {}; }
  double contactReach(const BodyReach&, const BodyReach&, const StepContext&) const override { return reach_; }
  double reachShare(const BodyReach&, const StepContext&) const override { return 0.5 * reach_; }
  double touchingGap() const override { return 0.0; }
  void clearContacts() override {}
  int addCandidate(const Contact&, const RigidBody&, const RigidBody&, double) override { return 0; }
  SolverStepReport solve(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                         const std::vector<Contact>& contacts, const StepContext& step) override;
  const std::vector<Contact>& eventContacts(const std::vector<Contact>& contacts) override { return contacts; }
  std::vector<ShownContact> touchedPoints(const std::vector<Contact>& contacts) const override;
  const std::vector<ContactManifold>& manifolds() const override { return noManifolds_; }

 private:
  static void moveBody(RigidBody& body, const BodyMotion& integrated, double dt);

  SolverSettings settings_;
  std::vector<BodyMotion> motions_;  // per body: this step's velocity half
  std::vector<std::uint32_t> begun_;  // the bodies beginStep integrated, ascending
  double reach_;  // the narrow phase's touching tolerance: only touching pairs matter
  std::vector<ContactManifold> noManifolds_;
};

}  // namespace physdbg
