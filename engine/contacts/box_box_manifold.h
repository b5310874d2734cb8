#pragma once
// The manifold of two boxes: the general builder's rule (reference face =
// the face of either box best aligned with the contact normal, the other
// box's most opposed face clipped against its side planes, points beyond
// the speculative distance dropped, at most four kept) specialised to boxes,
// so no supporting feature is built, nothing is allocated and the clipping
// runs in the reference box's frame (far-from-origin scenes lose no
// precision). Reentrant: all scratch is on the stack.
// Two differences from the general builder, both for warm starting: a
// clipped point's feature id names the incident edge and side plane (or the
// two side planes) it lies on, unique within the manifold, where the general
// builder hashes the clipping history and can give two points one id; and
// ties in choosing four of more points go to the first in polygon order
// rather than to round-off. Corner points carry the same ids in both.
#include "engine/colliders/box_collider.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"

namespace physdbg {

// `manifold.a` and `manifold.b` must already be set; points are overwritten.
// Any box-box ContactResult works (SAT or GJK/EPA): only its normal, and its
// points when no face is aligned well enough (edge against edge), are used.
void buildBoxBoxManifold(const BoxCollider& a, const Transform& ta, const BoxCollider& b, const Transform& tb,
                         const ContactResult& result, double speculativeDistance, ContactManifold& manifold);

}  // namespace physdbg
