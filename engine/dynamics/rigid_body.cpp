#include "engine/dynamics/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine/colliders/convex_mesh_collider.h"

namespace physdbg {
namespace {

std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Eigenvalues of a symmetric matrix are resolved to about this share of the
// largest; a smaller smallest principal moment is indistinguishable from zero.
constexpr double kSingularInertiaShare = 16.0 * DBL_EPSILON;

// Relative tolerance of an explicit tensor's symmetry and of its principal
// moments' triangle inequalities (a flat plate meets one with equality).
constexpr double kInertiaTolerance = 1e-9;

// The tensor scaled by a power of two (exact) so that its largest entry lies
// in [0.5, 1): eigenvalues and inverses of it neither over- nor underflow.
int scaleExponent(const Mat3& inertia) {
  int exponent = 0;
  std::frexp(inertia.cwiseAbs().maxCoeff(), &exponent);
  return exponent;
}

Mat3 scaled(const Mat3& matrix, int exponent) {
  return matrix.unaryExpr([exponent](double x) { return std::ldexp(x, exponent); });
}

// Ascending principal moments of a symmetric tensor (its lower triangle).
Vec3 principalMoments(const Mat3& inertia) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(inertia, Eigen::EigenvaluesOnly).eigenvalues();
}

// (I + I^T) / 2, halving first so that no finite tensor overflows; exactly I
// when I is symmetric.
Mat3 symmetricPart(const Mat3& inertia) {
  if (inertia == inertia.transpose()) return inertia;
  return 0.5 * inertia + 0.5 * inertia.transpose();
}

std::string singularMessage(const Vec3& moments, const char* what) {
  return std::string(what) + ": its smallest principal moment is " + figure(moments.minCoeff() / moments.maxCoeff()) +
         " of its largest (needs over " + figure(kSingularInertiaShare) +
         "; a rod or a point turns freely about some axis)";
}

// Inverse of a body's inertia tensor. The tensor is singular when it is not
// positive definite relative to its own scale (a rod has no moment about its
// axis), not when its entries are small: a body of 1e-150 kg is fine. Scaling
// by a power of two is exact, so wherever inverting directly works this gives
// the same bits. `origin` says where the tensor came from, for messages.
Mat3 inverseInertia(const Mat3& inertia, const std::string& origin) {
  if (!inertia.allFinite()) throw std::invalid_argument("inertia tensor overflows a double" + origin);
  const double largest = inertia.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) throw std::invalid_argument("inertia tensor underflows to zero" + origin);
  const int exponent = scaleExponent(inertia);
  const Mat3 unit = scaled(inertia, -exponent);
  const Vec3 moments = principalMoments(unit);
  if (!(moments.minCoeff() > kSingularInertiaShare * moments.maxCoeff()))
    throw std::invalid_argument(singularMessage(moments, "collider has a singular inertia tensor"));
  const Mat3 inverse = scaled(unit.inverse(), -exponent);
  if (!inverse.allFinite()) throw std::invalid_argument("inverse inertia tensor overflows a double" + origin);
  return inverse;
}

}  // namespace

BodyDefinition aboutCentreOfMass(BodyDefinition definition) {
  const auto* hull = dynamic_cast<const ConvexMeshCollider*>(definition.collider.get());
  if (hull == nullptr) return definition;
  // Re-centred points leave a centroid of rounding size: leave those be.
  const double size = hull->localBounds().halfExtents().norm();
  if (hull->centroid().norm() <= 1e-12 * size) return definition;
  std::vector<Vec3> points = hull->hullVertices();
  for (Vec3& point : points) point -= hull->centroid();
  definition.position += definition.orientation * hull->centroid();
  definition.collider = std::make_shared<ConvexMeshCollider>(points);
  return definition;
}

std::string inertiaTensorProblem(const Mat3& inertia) {
  if (!inertia.allFinite()) return "inertia tensor is not finite";
  const double largest = inertia.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return "inertia tensor is zero";
  if (!((inertia - inertia.transpose()).cwiseAbs().maxCoeff() <= kInertiaTolerance * largest))
    return "inertia tensor is not symmetric: entries (i, j) and (j, i) differ by more than 1e-9 of its largest entry";
  const Vec3 moments = principalMoments(scaled(symmetricPart(inertia), -scaleExponent(inertia)));
  if (!(moments.minCoeff() > kSingularInertiaShare * moments.maxCoeff()))
    return singularMessage(moments, "inertia tensor is not positive definite");
  // Ascending, so only the largest can exceed the sum of the other two.
  if (moments[2] > (moments[0] + moments[1]) * (1.0 + kInertiaTolerance))
    return "principal moments break the triangle inequality: the largest is " +
           figure(moments[2] / (moments[0] + moments[1])) +
           " times the sum of the other two (no mass distribution has more than 1)";
  return "";
}

RigidBody::RigidBody(const BodyDefinition& definition)
    : collider_(definition.collider),
      position_(definition.position),
      linearVelocity_(definition.linearVelocity),
      angularVelocity_(definition.angularVelocity),
      orientation_(definition.orientation),
      isStatic_(definition.isStatic),
      isKinematic_(definition.isKinematic),
      useGravity_(definition.useGravity),
      mass_(definition.mass),
      linearDrag_(definition.linearDrag),
      angularDrag_(definition.angularDrag),
      material_(definition.material),
      lockTranslation_(definition.lockTranslation),
      lockRotation_(definition.lockRotation),
      isSensor_(definition.isSensor),
      filter_(definition.filter) {
  if (!collider_) throw std::invalid_argument("body has no collider");
  for (int axis = 0; axis < 3; ++axis) hasLocks_ = hasLocks_ || lockTranslation_[axis] || lockRotation_[axis];
  if (!isFinite(position_) || !isFinite(linearVelocity_) || !isFinite(angularVelocity_) || !isFinite(orientation_))
    throw std::invalid_argument("body state is not finite");
  if (orientation_.norm() < 1e-12) throw std::invalid_argument("body orientation is a zero quaternion");
  orientation_.normalize();
  if (linearDrag_ < 0 || angularDrag_ < 0) throw std::invalid_argument("drag must not be negative");
  if (isStatic_ && isKinematic_) throw std::invalid_argument("a body cannot be both static and kinematic");
  if (definition.localInertia && !isDynamic())
    throw std::invalid_argument("a static or kinematic body has no inertia: nothing turns it");
  const ColliderKind kind = collider_->kind();
  if (isDynamic() &&
      (kind == ColliderKind::TriangleMesh || kind == ColliderKind::Heightfield || kind == ColliderKind::Triangle))
    throw std::invalid_argument(std::string("a ") + colliderKindName(kind) +
                                " has no volume and no inside: only a static or kinematic body can hold one");
  if (!isDynamic()) {  // infinite mass: nothing pushes it
    mass_ = 0.0;
    inverseMass_ = 0.0;
    localInertia_.setZero();
    localInverseInertia_.setZero();
    if (isStatic_) {
      linearVelocity_.setZero();
      angularVelocity_.setZero();
    }
    return;
  }
  if (!(mass_ > 0.0) || !std::isfinite(mass_)) throw std::invalid_argument("mass must be positive and finite");
  inverseMass_ = 1.0 / mass_;
  if (!std::isfinite(inverseMass_)) {
    throw std::invalid_argument("mass " + figure(mass_) + " kg is too small: its inverse overflows a double");
  }
  localInertia_ = explicitOrColliderInertia(definition);
  localInverseInertia_ = inverseInertia(
      localInertia_, definition.localInertia ? std::string(" (the body's explicit inertia)")
                                             : " (mass " + figure(mass_) + " kg times the collider's unit inertia)");
  isotropic_ = localInertia_ == localInertia_(0, 0) * Mat3::Identity();
  applyLocks();
}

// The definition's own tensor (checked, and made exactly symmetric), or the
// collider's for this mass.
Mat3 RigidBody::explicitOrColliderInertia(const BodyDefinition& definition) const {
  if (!definition.localInertia) return collider_->unitInertia() * mass_;
  const std::string problem = inertiaTensorProblem(*definition.localInertia);
  if (!problem.empty()) throw std::invalid_argument(problem);
  return symmetricPart(*definition.localInertia);
}

namespace {

// With rotation locks the body turns about the free world axes B alone, and a
// torque or impulse tau gives it B (B^T I B)^-1 B^T tau: the free axes' block
// of the world inertia inverted, zero elsewhere. Masking I^-1 tau instead
// (P I^-1 tau) ignores that the locks push back: a tilted box locked about x
// and z, given a torque about y, spun at tau_y (I^-1)_yy instead of tau_y / I_yy.
Mat3 constrainedInverseInertia(const Quat& orientation, const Mat3& localInertia, bool isotropic,
                               const std::array<bool, 3>& locks) {
  const Mat3 rotation = orientation.toRotationMatrix();
  const Mat3 inertia = isotropic ? localInertia : Mat3(rotation * localInertia * rotation.transpose());
  int free[3], count = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (!locks[axis]) free[count++] = axis;
  Mat3 result = Mat3::Zero();
  if (count == 1) {
    result(free[0], free[0]) = 1.0 / inertia(free[0], free[0]);
  } else if (count == 2) {
    const int i = free[0], j = free[1];
    const Eigen::Matrix2d block{{inertia(i, i), inertia(i, j)}, {inertia(j, i), inertia(j, j)}};
    const Eigen::Matrix2d inverse = block.inverse();
    result(i, i) = inverse(0, 0);
    result(i, j) = inverse(0, 1);
    result(j, i) = inverse(1, 0);
    result(j, j) = inverse(1, 1);
  }
  return result;
}

}  // namespace

Mat3 RigidBody::worldInverseInertia() const {
  const bool locked = lockRotation_[0] || lockRotation_[1] || lockRotation_[2];
  if (locked) return constrainedInverseInertia(orientation_, localInertia_, isotropic_, lockRotation_);
  if (isotropic_) return localInverseInertia_;  // the same about every axis
  const Mat3 rotation = orientation_.toRotationMatrix();
  return rotation * localInverseInertia_ * rotation.transpose();
}

void RigidBody::addForce(const Vec3& force, ForceMode mode) {
  if (!isDynamic()) return;
  switch (mode) {
    case ForceMode::Force: forceAccumulator_ += force; break;
    case ForceMode::Acceleration: accelerationAccumulator_ += force; break;
    case ForceMode::Impulse: velocityChange_ += force * inverseMass_; break;
    case ForceMode::VelocityChange: velocityChange_ += force; break;
  }
}

void RigidBody::addTorque(const Vec3& torque, ForceMode mode) {
  if (!isDynamic()) return;
  switch (mode) {
    case ForceMode::Force: torqueAccumulator_ += torque; break;
    case ForceMode::Acceleration: angularAccelerationAccumulator_ += torque; break;
    case ForceMode::Impulse: angularMomentumChange_ += torque; break;
    case ForceMode::VelocityChange: angularVelocityChange_ += torque; break;
  }
}

void RigidBody::addForceAtPoint(const Vec3& force, const Vec3& point, ForceMode mode) {
  addForce(force, mode);
  addTorque((point - position_).cross(force), mode);
}

void RigidBody::applyImpulseAtPoint(const Vec3& impulse, const Vec3& point) {
  if (!isDynamic()) return;
  linearVelocity_ += impulse * inverseMass_;
  angularVelocity_ += worldInverseInertia() * (point - position_).cross(impulse);
  applyLocks();
}

// Forces (and gravity) become this step's constant accelerations, so a step
// cut into substeps applies them evenly; impulses act once, right away.
void RigidBody::beginStep(const Vec3& gravity) {
  if (!isDynamic()) return;
  stepAcceleration_ = forceAccumulator_ * inverseMass_ + accelerationAccumulator_;
  if (useGravity_) stepAcceleration_ += gravity;
  const Mat3 inverseInertia = worldInverseInertia();
  stepAngularAcceleration_ = inverseInertia * torqueAccumulator_ + angularAccelerationAccumulator_;
  linearVelocity_ += velocityChange_;
  angularVelocity_ += inverseInertia * angularMomentumChange_ + angularVelocityChange_;
  applyLocks();
  forceAccumulator_.setZero();
  accelerationAccumulator_.setZero();
  velocityChange_.setZero();
  torqueAccumulator_.setZero();
  angularAccelerationAccumulator_.setZero();
  angularMomentumChange_.setZero();
  angularVelocityChange_.setZero();
}

MotionProperties RigidBody::motionProperties() const {
  MotionProperties properties;
  properties.acceleration = stepAcceleration_;
  properties.angularAcceleration = stepAngularAcceleration_;
  properties.linearDrag = linearDrag_;
  properties.angularDrag = angularDrag_;
  properties.localInertia = localInertia_;
  properties.isotropic = isotropic_;
  properties.lockTranslation = lockTranslation_;
  properties.lockRotation = lockRotation_;
  return properties;
}

void RigidBody::setMotion(const BodyMotion& motion) {
  if (isStatic_) return;
  position_ = motion.position;
  orientation_ = motion.orientation;
  linearVelocity_ = motion.linearVelocity;
  angularVelocity_ = motion.angularVelocity;
}

void RigidBody::translate(const Vec3& delta) {
  if (!isDynamic()) return;
  for (int axis = 0; axis < 3; ++axis) {
    if (!lockTranslation_[axis]) position_[axis] += delta[axis];
  }
}

void RigidBody::rotate(const Vec3& rotation) {
  if (!isDynamic()) return;
  Vec3 allowed = rotation;
  for (int axis = 0; axis < 3; ++axis) {
    if (lockRotation_[axis]) allowed[axis] = 0.0;
  }
  orientation_ = (rotationFromVector(allowed) * orientation_).normalized();
}

void RigidBody::applyLocks() {
  if (hasLocks_) lockVelocities(linearVelocity_, angularVelocity_, lockTranslation_, lockRotation_);
}

bool RigidBody::hasPendingForces() const {
  for (const Vec3* accumulator : {&forceAccumulator_, &accelerationAccumulator_, &velocityChange_, &torqueAccumulator_,
                                  &angularAccelerationAccumulator_, &angularMomentumChange_, &angularVelocityChange_}) {
    if (*accumulator != Vec3::Zero()) return true;
  }
  return false;
}

double RigidBody::kineticEnergy() const {
  if (isStatic_) return 0.0;
  const Vec3 bodySpin = orientation_.conjugate() * angularVelocity_;
  return 0.5 * mass_ * linearVelocity_.squaredNorm() + 0.5 * bodySpin.dot(localInertia_ * bodySpin);
}

Vec3 RigidBody::angularMomentum() const {
  if (isStatic_) return Vec3::Zero();
  return orientation_ * (localInertia_ * (orientation_.conjugate() * angularVelocity_));
}

bool RigidBody::hasFiniteState() const {
  return isFinite(position_) && isFinite(orientation_) && isFinite(linearVelocity_) && isFinite(angularVelocity_);
}

}  // namespace physdbg
