#include "engine/world.h"

#include <cmath>
#include <stdexcept>

namespace physdbg {

World::World(const WorldSettings& settings) : settings_(settings) {
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt)) throw std::invalid_argument("dt must be positive");
  if (!isFinite(settings.gravity)) throw std::invalid_argument("gravity must be finite");
}

BodyId World::addBody(const BodyDefinition& definition) {
  bodies_.emplace_back(definition);
  frozen_.push_back(false);
  return static_cast<BodyId>(bodies_.size() - 1);
}

void World::step() {
  stats_ = StepStats{};
  integrateVelocities();
  integratePositions();
  freezeNonFiniteBodies();
  ++stepCount_;
}

void World::integrateVelocities() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (frozen_[i] || bodies_[i].isStatic()) continue;
    bodies_[i].integrateVelocity(settings_.dt, settings_.gravity);
    ++stats_.integratedBodies;
  }
}

void World::integratePositions() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (frozen_[i] || bodies_[i].isStatic()) continue;
    bodies_[i].integratePosition(settings_.dt);
    ++stats_.awakeBodies;
  }
}

// A non-finite body is reported with the step it happened on, then frozen:
// it takes no further part in the simulation, so it cannot poison the others.
void World::freezeNonFiniteBodies() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (frozen_[i] || bodies_[i].hasFiniteState()) continue;
    frozen_[i] = true;
    faults_.push_back({static_cast<BodyId>(i), stepCount_ + 1, "position, orientation or velocity became NaN or Inf"});
  }
}

}  // namespace physdbg
