#include "engine/colliders/capsule_collider.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace physdbg {

CapsuleCollider::CapsuleCollider(double radius, double halfHeight) : radius_(radius), halfHeight_(halfHeight) {
  if (!std::isfinite(radius) || !std::isfinite(halfHeight) || radius <= 0.0 || halfHeight < 0.0) {
    throw std::invalid_argument("CapsuleCollider: radius must be > 0 and halfHeight >= 0, both finite");
  }
}

Vec3 CapsuleCollider::localSupport(const Vec3& direction) const {
  const double length = direction.norm();
  const Vec3 offset = length == 0.0 ? Vec3(0.0, radius_, 0.0) : Vec3(direction * (radius_ / length));
  return localCoreSupport(direction) + offset;
}

Aabb CapsuleCollider::localBounds() const {
  return Aabb::fromCenterHalfExtents(Vec3::Zero(), Vec3(radius_, halfHeight_ + radius_, radius_));
}

double CapsuleCollider::volume() const {
  const double r2 = radius_ * radius_;
  return std::numbers::pi * r2 * (2.0 * halfHeight_ + 4.0 / 3.0 * radius_);
}

// Cylinder plus two hemispheres; each hemisphere's own inertia is moved from
// its centre of mass (3r/8 from its flat face) to the capsule centre.
Mat3 CapsuleCollider::unitInertia() const {
  const double r = radius_;
  const double h = halfHeight_;
  const double cylinderMass = std::numbers::pi * r * r * 2.0 * h;
  const double hemisphereMass = 2.0 / 3.0 * std::numbers::pi * r * r * r;
  const double axial = cylinderMass * r * r / 2.0 + 2.0 * hemisphereMass * 0.4 * r * r;
  const double perpendicular = cylinderMass * (h * h / 3.0 + r * r / 4.0) +
                               2.0 * hemisphereMass * (0.4 * r * r + h * h + 0.75 * h * r);
  const double mass = cylinderMass + 2.0 * hemisphereMass;
  return Vec3(perpendicular, axial, perpendicular).asDiagonal() * (1.0 / mass);
}

}  // namespace physdbg
