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

// Inverse of a body's inertia tensor. The tensor is singular when it is not
// positive definite relative to its own scale (a rod has no moment about its
// axis), not when its entries are small: a body of 1e-150 kg is fine. Scaling
// by a power of two is exact, so wherever inverting directly works this gives
// the same bits.
Mat3 inverseInertia(const Mat3& inertia, double mass) {
  const std::string product = " (mass " + figure(mass) + " kg times the collider's unit inertia)";
  if (!inertia.allFinite()) throw std::invalid_argument("inertia tensor overflows a double" + product);
  const double largest = inertia.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) throw std::invalid_argument("inertia tensor underflows to zero" + product);
  int exponent = 0;
  std::frexp(largest, &exponent);
  const Mat3 unit = inertia.unaryExpr([exponent](double x) { return std::ldexp(x, -exponent); });
  const Vec3 moments = Eigen::SelfAdjointEigenSolver<Mat3>(unit, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(moments.minCoeff() > kSingularInertiaShare * moments.maxCoeff())) {
    throw std::invalid_argument("collider has a singular inertia tensor: its smallest principal moment is " +
                                figure(moments.minCoeff() / moments.maxCoeff()) + " of its largest (needs over " +
                                figure(kSingularInertiaShare) + "; a rod or a point turns freely about some axis)");
  }
  const Mat3 inverse = unit.inverse().unaryExpr([exponent](double x) { return std::ldexp(x, -exponent); });
  if (!inverse.allFinite()) throw std::invalid_argument("inverse inertia tensor overflows a double" + product);
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
      lockRotation_(definition.lockRotation) {
  if (!collider_) throw std::invalid_argument("body has no collider");
  for (int axis = 0; axis < 3; ++axis) hasLocks_ = hasLocks_ || lockTranslation_[axis] || lockRotation_[axis];
  if (!isFinite(position_) || !isFinite(linearVelocity_) || !isFinite(angularVelocity_) || !isFinite(orientation_))
    throw std::invalid_argument("body state is not finite");
  if (orientation_.norm() < 1e-12) throw std::invalid_argument("body orientation is a zero quaternion");
  orientation_.normalize();
  if (linearDrag_ < 0 || angularDrag_ < 0) throw std::invalid_argument("drag must not be negative");
  if (isStatic_ && isKinematic_) throw std::invalid_argument("a body cannot be both static and kinematic");
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
  localInertia_ = collider_->unitInertia() * mass_;
  localInverseInertia_ = inverseInertia(localInertia_, mass_);
  isotropic_ = localInertia_ == localInertia_(0, 0) * Mat3::Identity();
  applyLocks();
}

Mat3 RigidBody::worldInverseInertia() const {
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
