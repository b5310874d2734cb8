#pragma once
// One abstract base for every collision shape. The narrow phase only ever asks
// a collider for its support point (farthest point along a direction), so a new
// convex shape needs nothing but a local support function and its mass
// properties. Colliders are immutable and shared between bodies.
#include "engine/aabb.h"
#include "engine/math.h"

namespace physdbg {

// Triangle is one triangle of a TriangleMesh or Heightfield, made by the
// narrow phase for a test; TriangleMesh and Heightfield are level geometry,
// which only static and kinematic bodies hold and which has no support
// function worth calling (their localSupport scans every vertex).
enum class ColliderKind { Sphere, Box, Capsule, ConvexMesh, Triangle, TriangleMesh, Heightfield };

const char* colliderKindName(ColliderKind kind);

class Collider {
 public:
  virtual ~Collider() = default;

  virtual ColliderKind kind() const = 0;

  // Farthest point along `direction` in the collider's own frame. `direction`
  // need not be normalised and may be zero (any surface point is then fine).
  virtual Vec3 localSupport(const Vec3& direction) const = 0;

  virtual Aabb localBounds() const = 0;
  virtual double volume() const = 0;

  // Inertia tensor about the centre of mass, local axes, for a mass of 1 kg.
  virtual Mat3 unitInertia() const = 0;

  // Tight world box. The default rotates the local box; shapes with a cheaper
  // or tighter answer override it.
  virtual Aabb worldBounds(const Transform& transform) const;

  // Support point in world space: rotate the direction into the local frame,
  // ask the shape, and map the answer back.
  Vec3 support(const Transform& transform, const Vec3& direction) const {
    return transform.apply(localSupport(transform.rotation.conjugate() * direction));
  }
};

}  // namespace physdbg
