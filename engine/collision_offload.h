#pragma once
// A collision stage that runs outside the engine, such as the compute-shader
// one in gpu/. The engine cannot make a GL context, so whoever can (the
// physdbg command) builds one and hands it to the World, which then takes
// its broad phase from it and asks it to test the pairs whose shapes it
// handles; every other pair is tested on the CPU in the same step, and
// everything after the narrow phase (manifolds into the solver, events,
// islands, sleep) is the same code for both.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/broadphase/tree_options.h"
#include "engine/colliders/collider.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/world_settings.h"

namespace physdbg {

// One pair to test: body ids a < b, and the distance within which a separated
// pair still gets speculative manifold points (the solver's contactReach).
struct OffloadRequest {
  std::uint32_t a = 0, b = 0;
  double reach = 0.0;
};

// The answer for A then B, as collide() gives it, and the manifold
// buildManifold would build from it (impulses zero; the solver warm-starts).
struct OffloadedContact {
  ContactResult result;
  ContactManifold manifold;
};

class CollisionOffload {
 public:
  virtual ~CollisionOffload() = default;
  // The broad phase the world uses instead of its tree; it must report the
  // tree's pairs for the same calls.
  virtual std::unique_ptr<BroadPhase> makeBroadPhase(const DynamicAabbTreeOptions& options) = 0;
  virtual bool handles(ColliderKind a, ColliderKind b) const = 0;
  // out[i] answers requests[i]; every request's shapes are ones it handles.
  virtual void collide(const std::vector<RigidBody>& bodies, const std::vector<OffloadRequest>& requests,
                       std::vector<OffloadedContact>& out) = 0;
};

}  // namespace physdbg
