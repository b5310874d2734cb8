#pragma once
// A convex body against level geometry (a triangle mesh or a heightfield,
// triangle_source.h): the mesh's query gives
// the triangles near the body, each is tested as a convex shape of its own
// (sphere by closest point, every other shape by GJK/EPA), contacts on the
// mesh's inactive edges take the face normal (triangle_mesh_collider.h),
// and each triangle's manifold is built by clipping against its face.
//
// One pair of bodies can touch the mesh along several normals (a box in a
// V-shaped gully), so it gets a manifold per normal: manifolds whose normals
// agree to within mergeAngle are merged into one, which is what a floor of
// coplanar triangles gives, and their points are cut down to the outline of
// the merged patch and then to four (manifold_points.h). A box on a floor of
// triangles therefore gets the four corners a box floor gives it, whichever
// seams run underneath.
#include <cstdint>
#include <vector>

#include "engine/colliders/triangle_source.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/contacts/manifold_builder.h"
#include "engine/narrowphase/narrow_phase_options.h"

namespace physdbg {

// Storage reused from pair to pair so a mesh pair does not allocate.
struct MeshContactScratch {
  std::vector<std::uint32_t> triangles;
  std::vector<ContactManifold> found;  // per triangle, before merging
  std::vector<ManifoldPoint> merged;
  ManifoldScratch manifold;
};

// Where on a triangle a contact was given the face normal, for the debug
// draw's mesh layer: an inactive edge, a corner whose edges are inactive, or
// the face itself (GJK/EPA tilted the normal with the point inside).
enum class CorrectedFeature : std::int8_t { None = -1, Edge0, Edge1, Edge2, Corner0, Corner1, Corner2, Face };

// One triangle the narrow phase tested against a body.
struct MeshTriangleTest {
  std::uint32_t triangle = 0;
  CorrectedFeature corrected = CorrectedFeature::None;
};

struct MeshContactCounts {
  long long triangles = 0;  // triangles tested
  long long corrected = 0;  // contacts on inactive edges or vertices given the face normal
};

// Normals within this angle (radians) share a manifold: far below any bend a
// mesh shows (the active-edge threshold is 5 degrees), far above the
// rounding between two coplanar triangles' normals.
inline constexpr double meshMergeAngle = 1e-6;

// The manifolds between bodies a < b, one of which holds `mesh` (meshIsA
// says which), appended to `out` (their normals from a to b, points sorted
// by feature id), and the triangles it tested to `tested` (may be null).
// Points farther apart than `reach` are left out. Returns
// the pair's deepest answer (its normal and points from a to b), Separated
// with an infinite distance when no triangle is within reach.
ContactResult collideWithMesh(const TriangleSource& mesh, const Transform& meshPose, const Collider& convex,
                              const Transform& convexPose, bool meshIsA, std::uint32_t a, std::uint32_t b,
                              double reach, const NarrowPhaseOptions& options, MeshContactScratch& scratch,
                              std::vector<ContactManifold>& out, MeshContactCounts& counts,
                              std::vector<MeshTriangleTest>* tested = nullptr);

// One triangle of a mesh or heightfield (in its frame, placed by meshPose)
// against a convex collider: the narrow phase's answer, normal from the
// triangle to the convex shape. Where that answer is within `reach` and
// found on an inactive edge or corner, the face normal is substituted and
// the distance measured along it to the face's plane. `corrected` (may be
// null) says where, or None; `uncorrected` (may be null) gets the answer
// before the substitution.
ContactResult collideWithTriangle(const SourceTriangle& triangle, const Transform& meshPose, const Collider& convex,
                                  const Transform& convexPose, const NarrowPhaseOptions& options, double reach,
                                  CorrectedFeature* corrected = nullptr, ContactResult* uncorrected = nullptr);

}  // namespace physdbg
