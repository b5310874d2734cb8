#include "reports/stability_support.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg::reports {

BodyDefinition dynamicBox(const Vec3& center, const Vec3& halfExtents, double mass) {
  return dynamicBody(std::make_shared<BoxCollider>(halfExtents), center, mass);
}

BodyDefinition dynamicSphere(const Vec3& center, double radius, double mass) {
  return dynamicBody(std::make_shared<SphereCollider>(radius), center, mass);
}

BodyDefinition floorAt(const Vec3& center, double top, double halfWidth) {
  const double halfHeight = std::max(0.5, 0.05 * halfWidth);
  return staticBox(Vec3(center.x(), top - halfHeight, center.z()), Vec3(halfWidth, halfHeight, halfWidth));
}

std::vector<Vec3> positionsOf(const World& world) {
  std::vector<Vec3> positions;
  positions.reserve(world.bodyCount());
  for (const RigidBody& body : world.bodies()) positions.push_back(body.position());
  return positions;
}

double largestDisplacement(const World& world, const std::vector<Vec3>& start) {
  double largest = 0.0;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    if (world.bodies()[i].isStatic()) continue;
    largest = std::max(largest, (world.bodies()[i].position() - start[i]).norm());
  }
  return largest;
}

int runSteps(World& world, int steps) {
  for (int i = 0; i < steps; ++i) {
    world.step();
    if (!world.numericalFaults().empty()) return i + 1;
  }
  return steps;
}

double totalKineticEnergy(const World& world) {
  double energy = 0.0;
  for (const RigidBody& body : world.bodies()) {
    if (!body.isStatic()) energy += body.kineticEnergy();
  }
  return energy;
}

double largestSpeed(const World& world) {
  double largest = 0.0;
  for (const RigidBody& body : world.bodies()) largest = std::max(largest, body.linearVelocity().norm());
  return largest;
}

std::string format(const char* pattern, double a, double b, double c) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

std::string faultNote(const World& world) {
  if (world.numericalFaults().empty()) return "";
  const NumericalFault& first = world.numericalFaults().front();
  return "; " + std::to_string(world.numericalFaults().size()) + " numerical fault(s), first body " +
         std::to_string(first.body) + " at step " + std::to_string(first.step) + ": " + first.what;
}

}  // namespace physdbg::reports
