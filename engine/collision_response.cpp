#include "engine/collision_response.h"

#include <algorithm>

namespace physdbg {

double combineRestitution(const Material& a, const Material& b) { return std::max(a.restitution, b.restitution); }

bool respondToContact(RigidBody& a, RigidBody& b, const ContactResult& contact, const ResponseSettings& settings) {
  const Vec3& normal = contact.normal;  // from A to B
  const Vec3 point = 0.5 * (contact.pointA + contact.pointB);
  const Vec3 armA = point - a.position(), armB = point - b.position();
  const Vec3 relativeVelocity = (b.linearVelocity() + b.angularVelocity().cross(armB)) -
                                (a.linearVelocity() + a.angularVelocity().cross(armA));
  const double approach = relativeVelocity.dot(normal);
  if (approach > 0.0) return false;

  const double inverseMassSum = a.inverseMass() + b.inverseMass();
  if (inverseMassSum == 0.0) return false;

  const double excess = std::max(contact.depth - settings.allowedPenetration, 0.0);
  if (excess > 0.0) {
    const Vec3 push = normal * (settings.positionCorrection * excess / inverseMassSum);
    a.translate(-push * a.inverseMass());
    b.translate(push * b.inverseMass());
  }

  const Mat3 inverseInertiaA = a.worldInverseInertia(), inverseInertiaB = b.worldInverseInertia();
  const double angularTerm = normal.dot((inverseInertiaA * armA.cross(normal)).cross(armA) +
                                        (inverseInertiaB * armB.cross(normal)).cross(armB));
  const double restitution =
      -approach > settings.restitutionThreshold ? combineRestitution(a.material(), b.material()) : 0.0;
  const double impulse = -(1.0 + restitution) * approach / (inverseMassSum + angularTerm);
  a.applyImpulseAtPoint(-impulse * normal, point);
  b.applyImpulseAtPoint(impulse * normal, point);
  return true;
}

}  // namespace physdbg
