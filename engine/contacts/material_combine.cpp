#include "engine/contacts/material_combine.h"

#include <algorithm>
#include <cmath>

namespace physdbg {

double combine(CombineRule rule, double a, double b) {
  switch (rule) {
    case CombineRule::Average: return 0.5 * (a + b);
    case CombineRule::Minimum: return std::min(a, b);
    case CombineRule::Maximum: return std::max(a, b);
    case CombineRule::Multiply: return a * b;
    case CombineRule::GeometricMean: return std::sqrt(a * b);
  }
  return 0.0;
}

CombinedMaterial combineMaterials(const Material& a, const Material& b, CombineRule restitution,
                                  CombineRule friction) {
  return {combine(restitution, a.restitution, b.restitution), combine(friction, a.staticFriction, b.staticFriction),
          combine(friction, a.dynamicFriction, b.dynamicFriction)};
}

}  // namespace physdbg
