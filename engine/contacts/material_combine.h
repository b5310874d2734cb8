#pragma once
// How two bodies' materials combine into the pair's. Both solvers call this
// one function with the world's rules, so a pair bounces and slides the same
// under either, and a scene can pick Unity's rules (average) or Box2D's
// (largest restitution, geometric-mean friction).
#include <optional>

#include "engine/dynamics/material.h"

namespace physdbg {

enum class CombineRule { Average, Minimum, Maximum, Multiply, GeometricMean };

// An unset rule takes the solver's default (solver_settings.h): the seed
// solver follows the design (Unity: average for both); sequential impulses
// take the larger restitution (a rubber ball bounces on concrete) and the
// geometric-mean friction (a frictionless surface makes every pair on it
// frictionless, equal materials keep their value).
struct CombineRules {
  std::optional<CombineRule> restitution;
  std::optional<CombineRule> friction;
};

struct CombinedMaterial {
  double restitution = 0.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
};

double combine(CombineRule rule, double a, double b);
CombinedMaterial combineMaterials(const Material& a, const Material& b, CombineRule restitution,
                                  CombineRule friction);

}  // namespace physdbg
