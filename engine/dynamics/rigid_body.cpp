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

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Rotation by the vector `rotation` (axis times angle), exactly: keeps a spin
// about a fixed axis exact and the quaternion unit-length to round-off.
Quat rotationFromVector(const Vec3& rotation) {
  const double angle = rotation.norm();
  if (angle < 1e-300) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, rotation / angle));
}

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
  if (isStatic_) {
    mass_ = 0.0;
    inverseMass_ = 0.0;
    localInertia_.setZero();
    localInverseInertia_.setZero();
    linearVelocity_.setZero();
    angularVelocity_.setZero();
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
  if (isStatic_) return;
  switch (mode) {
    case ForceMode::Force: forceAccumulator_ += force; break;
    case ForceMode::Acceleration: accelerationAccumulator_ += force; break;
    case ForceMode::Impulse: velocityChange_ += force * inverseMass_; break;
    case ForceMode::VelocityChange: velocityChange_ += force; break;
  }
}

void RigidBody::addTorque(const Vec3& torque, ForceMode mode) {
  if (isStatic_) return;
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
  if (isStatic_) return;
  linearVelocity_ += impulse * inverseMass_;
  angularVelocity_ += worldInverseInertia() * (point - position_).cross(impulse);
  applyLocks();
}

void RigidBody::integrateVelocity(double dt, const Vec3& gravity) {
  beginStep(gravity);
  integrateVelocity(dt);
}

// Forces (and gravity) become this step's constant accelerations, so a step
// cut into substeps applies them evenly; impulses act once, right away.
void RigidBody::beginStep(const Vec3& gravity) {
  if (isStatic_) return;
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

void RigidBody::integrateVelocity(double dt) {
  if (isStatic_) return;
  linearVelocity_ += stepAcceleration_ * dt;
  linearVelocity_ /= 1.0 + linearDrag_ * dt;
  integrateAngularVelocity(dt);
  angularVelocity_ += stepAngularAcceleration_ * dt;
  angularVelocity_ /= 1.0 + angularDrag_ * dt;
  applyLocks();
}

// Torque-free part of Euler's equations, dPi/dt = Pi x w with Pi = I w in the
// body frame, by the implicit midpoint rule. Explicit Euler gains energy on a
// tumbling box (MuJoCo measured +9%); the midpoint rule keeps both invariants,
// |Pi| and the kinetic energy, to the Newton tolerance. Its solution satisfies
// Pi1 = C Pi0 with C the Cayley rotation of -dt*wm, so turning the body by C's
// inverse (angle 2 atan(dt |wm| / 2) about wm) keeps the world angular momentum
// R Pi exactly too. A spin about a principal axis (w x Iw = 0) is unchanged.
void RigidBody::integrateAngularVelocity(double dt) {
  // With a rotation lock the body is constrained, not free: the torque-free
  // equations do not apply, and the locks alone decide the spin. An
  // isotropic body (cube, sphere) has w x Iw = 0 for every w.
  const bool rotationLocked = lockRotation_[0] || lockRotation_[1] || lockRotation_[2];
  const Vec3 start = isotropic_ || rotationLocked ? Vec3::Zero() : Vec3(orientation_.conjugate() * angularVelocity_);
  const Mat3& inertia = localInertia_;
  if (start.cross(inertia * start).squaredNorm() == 0.0) {
    orientationSpin_ = angularVelocity_;
    spinAfterGyroscopicStep_ = angularVelocity_;
    return;
  }
  Vec3 end = start;
  for (int iteration = 0; iteration < 10; ++iteration) {
    const Vec3 middle = 0.5 * (start + end);
    const Vec3 residual = inertia * (end - start) + dt * middle.cross(inertia * middle);
    const Mat3 jacobian = inertia + 0.5 * dt * (skew(middle) * inertia - skew(inertia * middle));
    const Vec3 step = jacobian.partialPivLu().solve(residual);
    end -= step;
    if (step.norm() <= 1e-15 * end.norm()) break;
  }
  const Vec3 middle = orientation_ * (0.5 * (start + end));
  const double speed = middle.norm();
  orientationSpin_ = middle * (2.0 * std::atan(0.5 * dt * speed) / (dt * speed));
  angularVelocity_ = orientation_ * end;
  spinAfterGyroscopicStep_ = angularVelocity_;
}

// The orientation turns by the gyroscopic step's rotation plus whatever the
// torques, impulses and contacts added to the angular velocity since then.
void RigidBody::integratePosition(double dt) {
  if (isStatic_) return;
  position_ += linearVelocity_ * dt;
  const Vec3 spin = orientationSpin_ + (angularVelocity_ - spinAfterGyroscopicStep_);
  const Quat turn = rotationFromVector(spin * dt);
  orientation_ = (turn * orientation_).normalized();
  // The midpoint rule advanced the body-frame spin; it turns with the body.
  // (After a spin about a principal axis, `turn` is about w and leaves it be.)
  if (orientationSpin_ != spinAfterGyroscopicStep_) angularVelocity_ = turn * angularVelocity_;
  orientationSpin_.setZero();
  spinAfterGyroscopicStep_.setZero();
}

void RigidBody::translate(const Vec3& delta) {
  if (isStatic_) return;
  for (int axis = 0; axis < 3; ++axis) {
    if (!lockTranslation_[axis]) position_[axis] += delta[axis];
  }
}

void RigidBody::rotate(const Vec3& rotation) {
  if (isStatic_) return;
  Vec3 allowed = rotation;
  for (int axis = 0; axis < 3; ++axis) {
    if (lockRotation_[axis]) allowed[axis] = 0.0;
  }
  orientation_ = (rotationFromVector(allowed) * orientation_).normalized();
}

void RigidBody::applyLocks() {
  if (!hasLocks_) return;
  for (int axis = 0; axis < 3; ++axis) {
    if (lockTranslation_[axis]) linearVelocity_[axis] = 0.0;
    if (lockRotation_[axis]) angularVelocity_[axis] = 0.0;
  }
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
