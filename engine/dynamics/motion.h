#pragma once
// Semi-implicit Euler as free functions on a body's motion: velocities first,
// then positions with the new velocities. A solver integrates its own working
// copy through every substep and writes it back to the RigidBody once, so no
// integration state hides in RigidBody between the two halves.
#include <array>

#include "engine/math.h"

namespace physdbg {

// The wide contact solve loads and stores linearVelocity and angularVelocity
// as one run of six doubles (wide_contact_rows.cpp): keep the two together
// and in this order.
struct BodyMotion {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 linearVelocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();  // world frame, rad/s
  // The gyroscopic half of integrateVelocity leaves the spin integratePosition
  // turns the body by; what contacts add to angularVelocity in between is
  // added on top (see integratePosition). Zero outside a (sub)step.
  Vec3 orientationSpin = Vec3::Zero();
  Vec3 spinAfterGyroscopicStep = Vec3::Zero();
};

// What integration reads and never changes during a step.
struct MotionProperties {
  Vec3 acceleration = Vec3::Zero();         // m/s^2: forces and gravity this step
  Vec3 angularAcceleration = Vec3::Zero();  // rad/s^2, world frame
  // Per second: each integration of length h divides the velocity by
  // (1 + drag h), so over one second it falls to about exp(-drag) whatever
  // the step or substep length.
  double linearDrag = 0.0, angularDrag = 0.0;
  Mat3 localInertia = Mat3::Identity();
  bool isotropic = true;  // inertia c * identity: no gyroscopic term
  std::array<bool, 3> lockTranslation{false, false, false};  // world axes
  std::array<bool, 3> lockRotation{false, false, false};
};

// Velocity half of one integration of length h: accelerations, the
// torque-free gyroscopic step, drag, then axis locks.
void integrateVelocity(BodyMotion& motion, const MotionProperties& properties, double h);
// Position half: position and orientation move with the new velocities.
void integratePosition(BodyMotion& motion, double h);

// Zeroes velocities along locked axes. Locks act on velocities, so a locked
// coordinate keeps its exact initial value.
void lockVelocities(Vec3& linearVelocity, Vec3& angularVelocity, const std::array<bool, 3>& lockTranslation,
                    const std::array<bool, 3>& lockRotation);

// Rotation by the vector `rotation` (axis times angle), exactly: keeps a spin
// about a fixed axis exact and the quaternion unit-length to round-off.
Quat rotationFromVector(const Vec3& rotation);

}  // namespace physdbg
