#include "engine/baselines/seed_solver.h"

#include <algorithm>


namespace physdbg {

namespace {

Vec3 freeAxes(const std::array<bool, 3>& locks) {
  return {locks[0] ? 0.0 : 1.0, locks[1] ? 0.0 : 1.0, locks[2] ? 0.0 : 1.0};
}

// What a unit impulse along `normal` at `arm` changes in the body's velocity
// along the normal there, with locked axes taking no part.
double normalMobility(const RigidBody& body, const Vec3& arm, const Vec3& normal) {
  const Vec3 torque = arm.cross(normal);
  const Vec3 turn = (body.worldInverseInertia() * torque).cwiseProduct(freeAxes(body.lockRotation()));
  return body.inverseMass() * normal.cwiseProduct(freeAxes(body.lockTranslation())).dot(normal) + torque.dot(turn);
}

}  // namespace

// Each body is pushed at its own contact point, as the design's EPA gives
// them: A at its deepest point inside B, B at its deepest point inside A.
bool respondToContact(RigidBody& a, RigidBody& b, const ContactResult& contact, const SolverSettings& settings) {
  const Vec3& normal = contact.normal;  // from A to B
  const Vec3 armA = contact.pointA - a.position(), armB = contact.pointB - b.position();
  const Vec3 relativeVelocity = (b.linearVelocity() + b.angularVelocity().cross(armB)) -
                                (a.linearVelocity() + a.angularVelocity().cross(armA));
  const double approach = relativeVelocity.dot(normal);
  if (approach > 0.0) return false;

  const double inverseMassSum = a.inverseMass() + b.inverseMass();
  if (inverseMassSum == 0.0) return false;

  const double excess = std::max(contact.depth - settings.linearSlop, 0.0);
  if (excess > 0.0) {
    const Vec3 push = normal * (settings.seed.positionCorrection * excess / inverseMassSum);
    a.translate(-push * a.inverseMass());
    b.translate(push * b.inverseMass());
  }

  const double mobility = normalMobility(a, armA, normal) + normalMobility(b, armB, normal);
  if (!(mobility > 0.0)) return false;  // every axis that could separate them is locked
  const double restitution =
      -approach > settings.restitutionThreshold
          ? combine(settings.restitutionCombine(), a.material().restitution, b.material().restitution)
          : 0.0;
  const double impulse = -(1.0 + restitution) * approach / mobility;
  a.applyImpulseAtPoint(-impulse * normal, contact.pointA);
  b.applyImpulseAtPoint(impulse * normal, contact.pointB);
  return true;
}

SeedSolver::SeedSolver(const SolverSettings& settings, double touchingTolerance)
    : settings_(settings), reach_(touchingTolerance) {}

// The gyroscopic spin each body's velocity integration leaves is kept until
// its position moves in solve; a body woken in between keeps a zero one.
void SeedSolver::beginStep(std::vector<RigidBody>& bodies, const MovableBodies& movable, const StepContext& step) {
  motions_.resize(bodies.size());
  begun_ = movable.ids;
  for (const std::uint32_t id : movable.ids) {
    motions_[id] = bodies[id].motion();
    integrateVelocity(motions_[id], bodies[id].motionProperties(), step.dt);
    bodies[id].setMotion(motions_[id]);
  }
}

// Velocities are already this step's, so the box moves by v dt; the tight box
// is not swept (the seed solver has no speculative contacts to find).
PredictedMotion SeedSolver::predictMotion(const RigidBody& body, const StepContext& step) const {
  return {body.collider().worldBounds(body.transform()), body.linearVelocity() * step.dt};
}

// Contacts never involve frozen bodies: their proxies leave the broad phase
// before it runs.
SolverStepReport SeedSolver::solve(std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                   const std::vector<Contact>& contacts, const StepContext& step) {
  SolverStepReport report;
  for (const Contact& contact : contacts)
    if (respondToContact(bodies[contact.a], bodies[contact.b], contact.result, settings_)) ++report.responses;
  std::size_t begun = 0;
  for (const std::uint32_t id : movable.ids) {
    while (begun < begun_.size() && begun_[begun] < id) ++begun;
    const bool integrated = begun < begun_.size() && begun_[begun] == id;
    moveBody(bodies[id], integrated ? motions_[id] : BodyMotion{}, step.dt);
  }
  return report;
}

// The responses changed the body since beginStep; only the spin is taken
// from the velocity half.
void SeedSolver::moveBody(RigidBody& body, const BodyMotion& integrated, double dt) {
  BodyMotion motion = body.motion();
  motion.orientationSpin = integrated.orientationSpin;
  motion.spinAfterGyroscopicStep = integrated.spinAfterGyroscopicStep;
  integratePosition(motion, dt);
  body.setMotion(motion);
}

std::vector<ShownContact> SeedSolver::touchedPoints(const std::vector<Contact>& contacts) const {
  return physdbg::touchedPoints(contacts);
}

}  // namespace physdbg
