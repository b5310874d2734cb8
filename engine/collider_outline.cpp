#include "engine/collider_outline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"

namespace physdbg {
namespace {

using Outline = std::vector<OutlineSegment>;
using CirclePoints = std::array<Eigen::Vector2d, outlineCircleSegments + 1>;

// Cosine and sine of every step around the circle, the last equal to the
// first, computed once: every sphere and capsule of every frame reuses them.
const CirclePoints& unitCircle() {
  static const CirclePoints points = [] {
    CirclePoints table;
    for (int step = 0; step <= outlineCircleSegments; ++step) {
      const double angle = 2.0 * std::numbers::pi * (step % outlineCircleSegments) / outlineCircleSegments;
      table[step] = {std::cos(angle), std::sin(angle)};
    }
    return table;
  }();
  return points;
}

// Steps `first` .. `last` of the circle around `center` spanned by `along`
// (angle 0) and `across` (a quarter turn on), both of the circle's radius.
void appendArc(const Vec3& center, const Vec3& along, const Vec3& across, int first, int last, Outline& outline) {
  const CirclePoints& circle = unitCircle();
  const auto point = [&](int step) { return center + along * circle[step].x() + across * circle[step].y(); };
  for (int step = first; step < last; ++step) outline.push_back({point(step), point(step + 1)});
}

void appendCircle(const Vec3& center, const Vec3& along, const Vec3& across, Outline& outline) {
  appendArc(center, along, across, 0, outlineCircleSegments, outline);
}

// Great circles in the three coordinate planes of the body.
Outline sphereOutline(double radius) {
  Outline outline;
  const Vec3 x = Vec3::UnitX() * radius, y = Vec3::UnitY() * radius, z = Vec3::UnitZ() * radius;
  appendCircle(Vec3::Zero(), x, y, outline);
  appendCircle(Vec3::Zero(), y, z, outline);
  appendCircle(Vec3::Zero(), z, x, outline);
  return outline;
}

// The axis is local y. The cap arcs lie in the xy and zy planes, the ones
// holding the side lines, so arcs and lines join into two full silhouettes.
Outline capsuleOutline(double radius, double halfHeight) {
  Outline outline;
  const Vec3 x = Vec3::UnitX() * radius, y = Vec3::UnitY() * radius, z = Vec3::UnitZ() * radius;
  const Vec3 top = Vec3::UnitY() * halfHeight, bottom = -top;
  appendCircle(top, z, x, outline);
  appendCircle(bottom, z, x, outline);
  for (const Vec3& side : {x, Vec3(-x), z, Vec3(-z)}) outline.push_back({bottom + side, top + side});
  constexpr int half = outlineCircleSegments / 2;
  for (const Vec3& side : {x, z}) {
    appendArc(top, side, y, 0, half, outline);
    appendArc(bottom, side, y, half, outlineCircleSegments, outline);
  }
  return outline;
}

Outline boxOutline(const Vec3& halfExtents) {
  Outline outline;
  for (int axis = 0; axis < 3; ++axis) {
    const int first = (axis + 1) % 3, second = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      Vec3 end = halfExtents;
      end[first] *= corner & 1 ? 1.0 : -1.0;
      end[second] *= corner & 2 ? 1.0 : -1.0;
      Vec3 start = end;
      start[axis] = -end[axis];
      outline.push_back({start, end});
    }
  }
  return outline;
}

// The merged faces tile the hull's closed surface, each wound counter-
// clockwise from outside, so every edge is walked by its two faces in
// opposite directions: keeping the walk that goes up in vertex index draws
// it exactly once, with no search for the other face.
Outline hullOutline(const ConvexMeshCollider& hull) {
  Outline outline;
  const std::vector<Vec3>& vertices = hull.hullVertices();
  for (const HullFace& face : hull.hullFaces()) {
    const std::size_t count = face.vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
      const int from = face.vertices[i], to = face.vertices[(i + 1) % count];
      if (from < to) outline.push_back({vertices[from], vertices[to]});
    }
  }
  return outline;
}

// A mesh need not be closed nor consistently wound, so the hull's trick of
// keeping one walk per edge does not hold: its edges are sorted and each is
// drawn once.
Outline meshOutline(const std::vector<Vec3>& vertices, const std::vector<MeshTriangle>& triangles) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles.size());
  for (const MeshTriangle& triangle : triangles)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t p = triangle[e], q = triangle[(e + 1) % 3];
      edges.emplace_back(std::min(p, q), std::max(p, q));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Outline outline;
  outline.reserve(edges.size());
  for (const auto& [p, q] : edges) outline.push_back({vertices[p], vertices[q]});
  return outline;
}

}  // namespace

std::vector<OutlineSegment> localOutline(const Collider& collider) {
  switch (collider.kind()) {
    case ColliderKind::Sphere:
      return sphereOutline(static_cast<const SphereCollider&>(collider).radius());
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      return capsuleOutline(capsule.radius(), capsule.halfHeight());
    }
    case ColliderKind::Box:
      return boxOutline(static_cast<const BoxCollider&>(collider).halfExtents());
    case ColliderKind::ConvexMesh:
      return hullOutline(static_cast<const ConvexMeshCollider&>(collider));
    case ColliderKind::TriangleMesh: {
      const auto& mesh = static_cast<const TriangleMeshCollider&>(collider);
      return meshOutline(mesh.vertices(), mesh.triangles());
    }
    case ColliderKind::Heightfield: {
      std::vector<Vec3> vertices;
      std::vector<MeshTriangle> triangles;
      static_cast<const HeightfieldCollider&>(collider).sampledGrid(heightfieldDrawnCells, vertices, triangles);
      return meshOutline(vertices, triangles);
    }
    case ColliderKind::Triangle: {
      const auto& corners = static_cast<const TriangleCollider&>(collider).corners();
      return {{corners[0], corners[1]}, {corners[1], corners[2]}, {corners[2], corners[0]}};
    }
  }
  return {};
}

void emitOutline(const Collider& collider, const Transform& transform, debugdraw::Color color,
                 debugdraw::Frame& frame) {
  if (collider.kind() == ColliderKind::Box) {
    const Vec3& halfExtents = static_cast<const BoxCollider&>(collider).halfExtents();
    frame.wireBoxes.push_back({transform.position, transform.rotation, halfExtents, color});
    return;
  }
  for (const OutlineSegment& segment : localOutline(collider))
    frame.lines.push_back({transform.apply(segment.from), transform.apply(segment.to), color});
}

}  // namespace physdbg
