#pragma once
// The same scene in Bullet, for side-by-side benchmarks: spheres, boxes,
// capsules, convex hulls, triangle meshes (btBvhTriangleMeshShape, its
// quantised hierarchy) and heightfields (btHeightfieldTerrainShape), btDbvtBroadphase, btSequentialImpulseConstraintSolver with its
// default 10 iterations, one fixed substep per step.
//
// Bullet multiplies the friction and restitution of a pair where physdbg
// takes the geometric mean of friction and the larger restitution. When every
// body shares one material (the benchmark scenes), giving each Bullet body
// the square root of the value makes every pair combine to the same number.
#include <cstddef>
#include <memory>

#include "engine/math.h"
#include "scenes/scene.h"

namespace physdbg {
class TriangleMeshCollider;
}

namespace physdbg::bench {

class BulletWorld {
 public:
  // False when the project was built without Bullet.
  static bool available();
  // Milliseconds Bullet takes to build a btBvhTriangleMeshShape (quantised
  // hierarchy) over `mesh`'s triangles; 0 without Bullet.
  static double meshBuildMilliseconds(const TriangleMeshCollider& mesh);

  // Throws std::invalid_argument for a collider Bullet is not given here,
  // std::runtime_error when Bullet is not available.
  BulletWorld(const SceneDescription& scene, bool allowSleep);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  void step();
  // btContactSolverInfo::m_numIterations (Bullet's default is 10).
  void setSolverIterations(int iterations);
  std::size_t bodyCount() const;
  Vec3 position(std::size_t body) const;  // in scene order
  Vec3 linearVelocity(std::size_t body) const;
  // m: the deepest contact point of the manifolds the last step solved
  // (their distances are from before that step's integration); 0 when none overlap.
  double largestPenetration() const;
  double kineticEnergy() const;           // of the dynamic bodies, J
  // Pairs with a contact point no farther apart than `gap` (m): what
  // physdbg counts as touching pairs.
  int touchingPairs(double gap) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physdbg::bench
