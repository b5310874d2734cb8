#include "engine/dynamics/step_schedule.h"

#include <stdexcept>
#include <string>

namespace physdbg {
namespace {

void checkBody(BodyId id, const std::vector<RigidBody>& bodies) {
  if (id >= bodies.size()) throw std::invalid_argument("no body " + std::to_string(id));
}

}  // namespace

void checkScheduledForce(const ScheduledForce& force, const std::vector<RigidBody>& bodies) {
  checkBody(force.body, bodies);
  if (!bodies[force.body].isDynamic())
    throw std::invalid_argument("body " + std::to_string(force.body) + " is static or kinematic: forces cannot move it");
  if (force.isTorque && force.at) throw std::invalid_argument("a torque has no point of application");
  if (!isFinite(force.vector) || (force.at && !isFinite(*force.at)))
    throw std::invalid_argument("force vector and point must be finite");
  if (!(0 <= force.firstStep && force.firstStep < force.endStep))
    throw std::invalid_argument("force steps must be A < B with A >= 0");
}

void checkScheduledState(const ScheduledState& state, const std::vector<RigidBody>& bodies, int stepCount) {
  checkBody(state.body, bodies);
  if (bodies[state.body].isStatic())
    throw std::invalid_argument("body " + std::to_string(state.body) + " is static: its state cannot be set");
  if (!state.position && !state.orientation && !state.linearVelocity && !state.angularVelocity)
    throw std::invalid_argument("nothing to set: give a position, orientation, velocity or angular velocity");
  const auto finite = [](const std::optional<Vec3>& v) { return !v || isFinite(*v); };
  if (!finite(state.position) || !finite(state.linearVelocity) || !finite(state.angularVelocity) ||
      (state.orientation && !isFinite(*state.orientation)))
    throw std::invalid_argument("state values must be finite");
  if (state.orientation && !(state.orientation->norm() >= 1e-12))
    throw std::invalid_argument("orientation is a zero quaternion");
  if (state.step < stepCount) throw std::invalid_argument("step " + std::to_string(state.step) + " has passed");
}

void checkLifetime(const BodyLifetime& lifetime, const std::vector<BodyLifetime>& scheduled,
                   const std::vector<RigidBody>& bodies, int stepCount) {
  const BodyId id = lifetime.body;
  checkBody(id, bodies);
  for (const BodyLifetime& other : scheduled)
    if (other.body == id) throw std::invalid_argument("body " + std::to_string(id) + " already has a lifetime");
  if (lifetime.addAtStep < 0) throw std::invalid_argument("add step must not be negative");
  if (lifetime.removeAtStep && *lifetime.removeAtStep <= lifetime.addAtStep)
    throw std::invalid_argument("remove step must come after the add step");
  if (lifetime.addAtStep < stepCount && lifetime.addAtStep > 0)
    throw std::invalid_argument("add step " + std::to_string(lifetime.addAtStep) + " has passed");
  if (lifetime.removeAtStep && *lifetime.removeAtStep <= stepCount)
    throw std::invalid_argument("remove step " + std::to_string(*lifetime.removeAtStep) + " has passed");
}

}  // namespace physdbg
