#pragma once
// What the solver remembers of a step for the next one: each manifold's pair
// and, per point, its feature id, its anchor in A's frame and the impulses it
// ended with. A warm start reads nothing else, so the last step's manifolds
// (616 bytes each, four point slots whatever their count) are not kept a
// step longer: a one-point sphere contact is remembered in 72 bytes.
//
// Impulses of points that persist (same pair, same feature id) carry over. A
// point whose features changed takes the impulse of the nearest old point
// left unmatched within `reach` in A's frame: where two equal faces meet edge
// to edge, a sway of a micrometre moves a corner across the other face's side
// and the clip makes a new point in the same place. Losing its impulse would
// drop the load it held for a step and kick the stack.
//
// A pair against a triangle mesh can have a manifold per normal
// (mesh_contacts.h): there each manifold takes from the old one of its pair
// whose normal is nearest, if within about 8 degrees, so a body resting in a
// gully does not hand one face's impulses to the other.
#include <cstdint>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/contacts/contact_manifold.h"

namespace physdbg {

class TaskSystem;

class WarmStartMemory {
 public:
  // Remembers `manifolds` (in pair order), forgetting what was remembered.
  void remember(const std::vector<ContactManifold>& manifolds);
  // Each manifold of `manifolds` (in pair order) takes the remembered
  // impulses of its pair's points. `tasks` may be null; ranges of manifolds
  // run in parallel, and each meets the same remembered one for any split.
  void carryInto(std::vector<ContactManifold>& manifolds, double reach, const TaskSystem* tasks) const;
  std::size_t size() const { return manifolds_.size(); }

 private:
  struct Point {
    Vec3 localA;
    std::uint32_t featureId;
    double normalImpulse, tangentImpulse[2];
  };
  struct Manifold {
    BodyPair pair;
    std::uint32_t firstPoint;
    std::uint32_t pointCount;
    Eigen::Vector3f normal;  // only compared, between the manifolds of one pair
  };
  void carry(const Manifold& old, ContactManifold& manifold, double reach) const;

  std::vector<Manifold> manifolds_;
  std::vector<Point> points_;
};

}  // namespace physdbg
