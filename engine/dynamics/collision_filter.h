#pragma once
// Which bodies may touch, as Box2D's category and mask bits: a body is in
// the layers of `layer` and touches the layers of `collidesWith`; two bodies
// touch only when each is in a layer the other touches. The world drops
// pairs that may not touch as soon as the broad phase finds them, so they
// reach no narrow phase, no solver and no picture of candidate pairs.
#include <cstdint>

namespace physdbg {

struct CollisionFilter {
  std::uint32_t layer = 1u;            // bit k: in layer k
  std::uint32_t collidesWith = ~0u;    // bit k: touches bodies in layer k
  bool allows(const CollisionFilter& other) const {
    return (layer & other.collidesWith) != 0 && (other.layer & collidesWith) != 0;
  }
  bool isDefault() const { return layer == 1u && collidesWith == ~0u; }
};

}  // namespace physdbg
