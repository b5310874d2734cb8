#pragma once
// The `wire` layer draws each collider's true outline, not its bounding box:
// a box drawn around a sphere hides whether the sphere is round, where it
// touches and how it spins. A sphere gets three great circles fixed in its
// body (so rotation shows), a capsule its end circles, side lines and cap
// arcs (its silhouette from any side), a box its twelve edges, a convex hull
// the edges of its merged faces (no triangle diagonals inside a flat face),
// a triangle mesh every edge of its triangles once, a heightfield its cells'
// edges and diagonals (sampled: at most heightfieldDrawnCells cells a side).
//
// Nothing is cached per collider: the only search a hull would need (drawing
// each edge once) is avoided by the hull's winding, so the work per frame is
// the lines themselves.
#include <vector>

#include "debugdraw/primitives.h"
#include "engine/colliders/collider.h"
#include "engine/math.h"

namespace physdbg {

// Segments per full circle. At 1280x720 a sphere filling the view's height
// strays from a true circle by under 2 px; a sphere costs 3 x 40 lines.
inline constexpr int outlineCircleSegments = 40;
// A 1000 x 1000 field is 3 million lines; 256 a side (200,000) draws in tens
// of ms and shows the terrain's shape, every fourth sample of such a field.
inline constexpr int heightfieldDrawnCells = 256;

struct OutlineSegment {
  Vec3 from, to;
};

// The collider's outline in its own frame: sphere 3 x 40 segments, capsule
// 2 x 40 + 4 + 4 x 20, box 12, hull one per edge.
std::vector<OutlineSegment> localOutline(const Collider& collider);

// Appends the outline placed by `transform`: a box as one WireBox (the
// renderer draws those instanced), every other shape as lines.
void emitOutline(const Collider& collider, const Transform& transform, debugdraw::Color color,
                 debugdraw::Frame& frame);

}  // namespace physdbg
