#pragma once
// Box against box by the separating-axis test, in place of GJK + EPA.
//
// Two boxes are disjoint exactly when one of 15 axes separates their
// projections: the three face normals of each and the nine cross products of
// an edge direction of each. When they overlap, the smallest overlap over
// those axes is the exact penetration depth and its axis the exact normal
// (for polytopes the minimum translation is normal to a face of the Minkowski
// difference, and a box pair's faces are normal to exactly those axes), so
// the answer agrees with EPA to round-off while costing a fixed, small amount.
// Witness points come from the features the axis names: a face axis clips
// the other box's most opposed face against the face's rectangle and takes
// the deepest point; an edge axis takes the closest points of the two edges.
//
// Separated pairs: the largest separation over the axes is only a lower
// bound on the distance. It is the distance when the closest features are a
// face and something (a face axis) or two crossing edges (an edge axis), and
// the witness points then prove it: their gap equals the bound. Otherwise
// (vertex against vertex or edge, parallel edges side by side, seen from a
// face at an angle) the closest direction is none of the 15 and this returns
// nothing, so the caller runs GJK for the exact distance. Exact distances are
// kept because the solver's reach test, the touching gap and contact events
// all compare against them; a lower bound would admit pairs that are in fact
// farther apart.
#include <optional>

#include "engine/colliders/box_collider.h"
#include "engine/contacts/contact.h"

namespace physdbg {

// Same conventions as collide(): normal from A to B, points in world space,
// status from the signed distance and `touchingTolerance`; usedBoxBox set.
// Rotations must be unit quaternions. Returns nothing when the pair is
// separated (or within the touching tolerance) but the distance is not one
// of the axes' separations (see above): the caller must ask GJK.
std::optional<ContactResult> collideBoxes(const BoxCollider& a, const Transform& ta, const BoxCollider& b,
                                          const Transform& tb, double touchingTolerance);

}  // namespace physdbg
