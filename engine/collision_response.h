#pragma once
// The design's collision response (CollisionResponseWithRotation): for one
// contact, skip it when the bodies already separate at the contact point,
// push them apart along the normal in proportion to their inverse masses, then
// apply one impulse through the contact point that uses both inverse world
// inertia tensors and the combined restitution.
#include "engine/dynamics/rigid_body.h"
#include "engine/narrowphase/contact.h"

namespace physdbg {

struct ResponseSettings {
  // Share of the penetration (beyond the allowed one) removed per step: the
  // design's editable damping. 1 removes it at once, smaller is softer.
  double positionCorrection = 0.8;
  // Penetration left in place so a resting contact stays a contact and does
  // not flicker between touching and separated every step.
  double allowedPenetration = 0.005;
  // Below this approach speed (m/s) contacts do not bounce: a resting body
  // with restitution would otherwise hop on gravity's dt*g every step.
  double restitutionThreshold = 0.2;
};

// Restitution of a pair is the larger of the two: a rubber ball bounces on a
// concrete floor. Documented in scenes/README.md.
double combineRestitution(const Material& a, const Material& b);

// Returns false when the pair was skipped because it already separates.
bool respondToContact(RigidBody& a, RigidBody& b, const ContactResult& contact, const ResponseSettings& settings);

}  // namespace physdbg
