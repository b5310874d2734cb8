#include "engine/contacts/material_combine.h"

#include <algorithm>
#include <cmath>

namespace physdbg {

CombinedMaterial combineMaterials(const Material& a, const Material& b) {
  return {std::max(a.restitution, b.restitution), std::sqrt(a.staticFriction * b.staticFriction),
          std::sqrt(a.dynamicFriction * b.dynamicFriction)};
}

}  // namespace physdbg
