#include "engine/narrowphase/analytic_contacts.h"

#include <cmath>

namespace physdbg {

ContactResult classifyContact(double signedDistance, const Vec3& normal, const Vec3& pointA, const Vec3& pointB,
                              double touchingTolerance) {
  ContactResult result;
  result.normal = normal;
  result.pointA = pointA;
  result.pointB = pointB;
  if (signedDistance > touchingTolerance) {
    result.status = ContactStatus::Separated;
    result.distance = signedDistance;
  } else if (signedDistance >= -touchingTolerance) {
    result.status = ContactStatus::Touching;
  } else {
    result.status = ContactStatus::Penetrating;
    result.depth = -signedDistance;
  }
  return result;
}

ContactResult collideSpheres(const SphereCollider& a, const Vec3& centreA, const SphereCollider& b,
                             const Vec3& centreB, double touchingTolerance) {
  const Vec3 delta = centreB - centreA;
  const double distance = delta.norm();
  const Vec3 normal = distance > 0.0 ? Vec3(delta / distance) : Vec3::UnitY();
  return classifyContact(distance - a.radius() - b.radius(), normal, centreA + a.radius() * normal,
                         centreB - b.radius() * normal, touchingTolerance);
}

ContactResult collideBoxSphere(const BoxCollider& box, const Transform& boxTransform, const SphereCollider& sphere,
                               const Vec3& sphereCentre, double touchingTolerance) {
  const Vec3 local = boxTransform.applyInverse(sphereCentre);
  const Vec3& half = box.halfExtents();
  const Vec3 clamped = local.cwiseMax(-half).cwiseMin(half);
  const Vec3 outside = local - clamped;
  const double gap = outside.norm();
  Vec3 localNormal;
  Vec3 localPoint = clamped;
  double signedDistance;
  if (gap > 0.0) {
    localNormal = outside / gap;
    signedDistance = gap - sphere.radius();
  } else {
    const Vec3 faceDistance = half - local.cwiseAbs();
    int axis = 0;
    faceDistance.minCoeff(&axis);
    localNormal = Vec3::Zero();
    localNormal[axis] = local[axis] < 0.0 ? -1.0 : 1.0;
    localPoint[axis] = localNormal[axis] * half[axis];
    signedDistance = -faceDistance[axis] - sphere.radius();
  }
  const Vec3 normal = boxTransform.rotation * localNormal;
  return classifyContact(signedDistance, normal, boxTransform.apply(localPoint),
                         sphereCentre - sphere.radius() * normal, touchingTolerance);
}

ContactResult swapped(const ContactResult& result) {
  ContactResult out = result;
  out.normal = -result.normal;
  out.pointA = result.pointB;
  out.pointB = result.pointA;
  return out;
}

}  // namespace physdbg
