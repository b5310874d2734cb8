#include "cli/step_series.h"

#include <cstdio>

#include "engine/world.h"

namespace physdbg::cli {

SeriesRow measureSeries(const World& world, double stepMilliseconds) {
  SeriesRow row;
  row.step = world.stepCount();
  row.time = world.time();
  const Vec3 gravity = world.settings().gravity;
  Vec3 momentum = Vec3::Zero(), angular = Vec3::Zero();
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const BodyId id = static_cast<BodyId>(i);
    const RigidBody& body = world.body(id);
    if (!body.isDynamic() || world.isFrozen(id) || !world.isPresent(id)) continue;  // absent: not in the run
    row.kineticEnergy += body.kineticEnergy();
    if (body.usesGravity()) row.potentialEnergy -= body.mass() * gravity.dot(body.position());
    const Vec3 linear = body.mass() * body.linearVelocity();
    momentum += linear;
    angular += body.position().cross(linear) + body.angularMomentum();
  }
  row.linearMomentum = momentum.norm();
  row.angularMomentum = angular.norm();
  const StepStats& stats = world.lastStepStats();
  row.contacts = stats.contacts;
  row.maxPenetration = stats.largestPenetration;
  row.awake = stats.awakeBodies;
  row.substeps = stats.substeps;
  row.stepMilliseconds = stepMilliseconds;
  return row;
}

void SeriesWriter::write(const SeriesRow& row) {
  char line[512];
  std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%d,%d,%.17g\n", row.step, row.time,
                row.kineticEnergy, row.potentialEnergy, row.linearMomentum, row.angularMomentum, row.contacts,
                row.maxPenetration, row.awake, row.substeps, row.stepMilliseconds);
  output_.writeLine(line);
  output_.check();
}

}  // namespace physdbg::cli
