#pragma once
// Builds a contact manifold from one narrow-phase result: the supporting
// features of both shapes along the contact normal are clipped against each
// other (reference face / incident feature), points farther apart than
// `speculativeDistance` are dropped, and at most four are kept.
#include <vector>

#include "engine/colliders/collider.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/contacts/supporting_feature.h"
#include "engine/contacts/contact.h"

namespace physdbg {

// Reusable scratch storage so building a manifold does not allocate.
struct ManifoldScratch {
  SupportingFeature featureA, featureB;
  struct TaggedPoint {
    Vec3 point;
    std::uint32_t tag;
  };
  std::vector<TaggedPoint> polygon, clipped;
  std::vector<ManifoldPoint> kept;
};

// `manifold.a` and `manifold.b` must already be set; points are overwritten.
// Impulses are zero: warm starting is the solver's business. A box pair the
// box-box narrow phase decided (result.usedBoxBox) goes to
// buildBoxBoxManifold, which gives the same points and feature ids without
// allocating; every other pair to buildGeneralManifold.
void buildManifold(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                   const ContactResult& result, double speculativeDistance, ManifoldScratch& scratch,
                   ContactManifold& manifold);

// Supporting features of any two shapes clipped in world space; the
// reference the box-box builder is tested against.
void buildGeneralManifold(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                          const ContactResult& result, double speculativeDistance, ManifoldScratch& scratch,
                          ContactManifold& manifold);

}  // namespace physdbg
