#pragma once
// How manifold points are made, and which four a manifold keeps: shared by
// the general manifold builder and the box-box one, so both follow the same
// rules and give a box pair the same points.
#include <cstdint>
#include <span>

#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"

namespace physdbg {

// The reference face must face the contact normal to within about 18 degrees;
// otherwise (edge against edge, a vertex into a face at an angle) the single
// narrow-phase point is the contact.
inline constexpr double minimumFaceAlignment = 0.95;
// A's face stays the reference unless B's is better aligned by more than
// this (cosine), so the choice does not flicker between steps when both are
// equally good (a box resting squarely on another).
inline constexpr double referenceFaceHysteresis = 1e-3;
// Metres; far below any visible offset, far above double round-off at 1e5 m.
// Points within it outside a side plane count as inside: a box resting
// squarely on another has its corners exactly on the side planes, and without
// the tolerance round-off would turn them into intersection points one step
// and back the next, changing their feature ids and losing warm starting.
inline constexpr double clipTolerance = 1e-6;

// Appends a point from its world positions; local anchors from the transforms.
void addPoint(ContactManifold& manifold, const Transform& ta, const Transform& tb, const Vec3& pointA,
              const Vec3& pointB, std::uint32_t featureId);

// The narrow phase's own point as the whole manifold (feature id 0).
void singlePoint(const Transform& ta, const Transform& tb, const ContactResult& result, ContactManifold& manifold);

// Keeps the deepest point, the one farthest from it, then the points that
// add the most area: four points spanning the contact resist any tipping.
// `manifold.normal` must be set; its points are overwritten. A later point
// replaces the best so far only when better by more than `tieMargin` of the
// points' spread (squared for areas). Rectangles clipped by rectangles tie
// exactly (points on parallel edges add equal areas); with a margin the
// first in polygon order wins every step, where round-off would pick one
// this step and another the next, and the points' warm starts with them.
void reduceToFour(ContactManifold& manifold, std::span<const ManifoldPoint> points, double tieMargin = 0.0);

}  // namespace physdbg
