#pragma once
// What a run schedules ahead: forces, state changes and lifetimes, each with
// the steps it applies at, and the checks every one passes before it is
// accepted (a refused one throws std::invalid_argument naming the body and
// the problem). World applies them as the run reaches their steps.
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/dynamics/rigid_body.h"
#include "engine/math.h"

namespace physdbg {

using BodyId = std::uint32_t;

// A force, torque, impulse or velocity change (its ForceMode) applied to one
// dynamic body at every step s with firstStep <= s < endStep, before the step
// integrates. A force through a world point `at` off the centre of mass also
// turns the body (torque (at - centre) x force).
struct ScheduledForce {
  BodyId body = 0;
  Vec3 vector = Vec3::Zero();  // N, m/s^2, N s or m/s (torques: N m, ...)
  bool isTorque = false;
  ForceMode mode = ForceMode::Force;
  std::optional<Vec3> at;
  int firstStep = 0, endStep = 1;
};

// A change of one body's state when step `step` begins (step 0 is the first),
// as ScheduledForce's firstStep: the world after `step` steps is replaced by
// it, before forces and gravity act. Each given part replaces the body's
// own; at least one must be given. A sleeping body that is set wakes with its
// island; a kinematic body may be set (it then moves with the new values).
struct ScheduledState {
  BodyId body = 0;
  int step = 0;
  std::optional<Vec3> position;  // m, the centre of mass
  std::optional<Quat> orientation;  // normalised when applied; not zero
  std::optional<Vec3> linearVelocity;   // m/s
  std::optional<Vec3> angularVelocity;  // rad/s, world frame
};

// When a body takes part in the run: in the states s (the world after s
// steps) with addAtStep <= s < removeAtStep. Ids never change, so a body
// added later keeps the id (the scene index) it was created with.
struct BodyLifetime {
  BodyId body = 0;
  int addAtStep = 0;
  std::optional<int> removeAtStep;
};

// Throws std::invalid_argument for an unknown, static or kinematic body, a
// torque with a point, non-finite vectors or an empty step range.
void checkScheduledForce(const ScheduledForce& force, const std::vector<RigidBody>& bodies);
// Throws std::invalid_argument for an unknown or static body, nothing to
// set, non-finite values, a zero orientation or a step before `stepCount`.
void checkScheduledState(const ScheduledState& state, const std::vector<RigidBody>& bodies, int stepCount);
// Throws std::invalid_argument for an unknown body, a second lifetime for it
// (among `scheduled`), a negative addAtStep, removeAtStep <= addAtStep or a
// step the run (at `stepCount`) has passed.
void checkLifetime(const BodyLifetime& lifetime, const std::vector<BodyLifetime>& scheduled,
                   const std::vector<RigidBody>& bodies, int stepCount);

}  // namespace physdbg
