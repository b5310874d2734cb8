#pragma once
// Small builders and measurements shared by the stability cases.
#include <string>
#include <vector>

#include "engine/world.h"
#include "scenes/body_builders.h"
#include "scenes/scene.h"

namespace physdbg::reports {

BodyDefinition dynamicBox(const Vec3& center, const Vec3& halfExtents, double mass = 1.0);
BodyDefinition dynamicSphere(const Vec3& center, double radius, double mass = 1.0);

// A static slab whose top face is at `top` (y), centred on `center` in x/z.
BodyDefinition floorAt(const Vec3& center, double top, double halfWidth);

// Positions of every body, in body order.
std::vector<Vec3> positionsOf(const World& world);

// Largest distance any dynamic body moved from `start`.
double largestDisplacement(const World& world, const std::vector<Vec3>& start);

// Steps `steps` times; returns how many steps ran before a numerical fault
// (or `steps`).
int runSteps(World& world, int steps);

double totalKineticEnergy(const World& world);

double largestSpeed(const World& world);

// printf-style formatting of up to three numbers.
std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0);

// "12 faults" style suffix, empty when there are none.
std::string faultNote(const World& world);

}  // namespace physdbg::reports
