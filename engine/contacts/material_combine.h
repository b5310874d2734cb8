#pragma once
// How two bodies' materials combine into the pair's. Both solvers call this
// one function, so a pair bounces and slides the same under either.
#include "engine/dynamics/material.h"

namespace physdbg {

struct CombinedMaterial {
  double restitution = 0.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
};

// Restitution: the larger of the two, so a rubber ball bounces on a concrete
// floor. Friction: the geometric mean, so a frictionless surface makes every
// pair on it frictionless and equal materials keep their value. Documented
// in scenes/README.md.
CombinedMaterial combineMaterials(const Material& a, const Material& b);

}  // namespace physdbg
