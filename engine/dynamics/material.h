#pragma once
// Surface properties of a body. How two materials combine into a pair's is
// engine/contacts/material_combine.h.
namespace physdbg {

struct Material {
  double restitution = 0.0;      // 0 = no bounce, 1 = elastic
  double staticFriction = 0.6;   // Coulomb coefficient that holds a body at rest
  double dynamicFriction = 0.5;  // Coulomb coefficient while sliding
};

}  // namespace physdbg
