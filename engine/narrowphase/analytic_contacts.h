#pragma once
// Closed-form contacts for the pairs a sphere-only scene needs; the general
// GJK/EPA path gives the same answers (checked in the tests) but slower.
#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/contacts/contact.h"

namespace physdbg {

// Signed-distance form shared by every path: classifies against the touching
// tolerance and fills distance/depth. `signedDistance` < 0 means overlap.
ContactResult classifyContact(double signedDistance, const Vec3& normal, const Vec3& pointA, const Vec3& pointB,
                              double touchingTolerance);

// Coincident centres get the normal +y (any unit vector is a valid answer).
ContactResult collideSpheres(const SphereCollider& a, const Vec3& centreA, const SphereCollider& b,
                             const Vec3& centreB, double touchingTolerance);

// Normal from the box to the sphere. A centre inside the box pushes out
// through the nearest face (the lowest axis wins ties).
ContactResult collideBoxSphere(const BoxCollider& box, const Transform& boxTransform, const SphereCollider& sphere,
                               const Vec3& sphereCentre, double touchingTolerance);

// Swaps the roles of A and B: normal reversed, points exchanged.
ContactResult swapped(const ContactResult& result);

}  // namespace physdbg
