#include "engine/narrowphase/mesh_contacts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "engine/colliders/sphere_collider.h"
#include "engine/contacts/manifold_points.h"
#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/narrow_phase.h"

namespace physdbg {
namespace {

// Barycentric coordinates within this of 0 put a point on the edge or
// corner they name: far above GJK/EPA's relative error (1e-12), far below
// any distance a contact point is placed by.
constexpr double onFeatureTolerance = 1e-7;

// The closest point of triangle abc to p, by the Voronoi regions of its
// corners, edges and face.
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double scale = 1.0 / (va + vb + vc);
  return a + ab * (vb * scale) + ac * (vc * scale);
}

// A sphere against a triangle (mesh frame): the closest point gives the
// normal; a centre on the triangle itself takes the face normal.
ContactResult sphereTriangle(const TriangleCollider& triangle, const Transform& meshPose, const SphereCollider& sphere,
                             const Vec3& centre, double touchingTolerance) {
  const Vec3 local = meshPose.applyInverse(centre);
  const auto& corners = triangle.corners();
  const Vec3 closest = closestOnTriangle(local, corners[0], corners[1], corners[2]);
  const Vec3 offset = local - closest;
  const double distance = offset.norm();
  const Vec3 localNormal = distance > 0.0 ? Vec3(offset / distance) : triangle.normal();
  const Vec3 normal = meshPose.rotation * localNormal;
  return classifyContact(distance - sphere.radius(), normal, meshPose.apply(closest),
                         centre - sphere.radius() * normal, touchingTolerance);
}

// The barycentric coordinates of `point` (mesh frame) projected onto the
// triangle's plane: one per corner, summing to 1.
Vec3 barycentric(const SourceTriangle& triangle, const Vec3& point) {
  const Vec3& a = triangle.corners[0];
  const Vec3 e1 = triangle.corners[1] - a, e2 = triangle.corners[2] - a, p = point - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2), dp1 = p.dot(e1), dp2 = p.dot(e2);
  const double denominator = d11 * d22 - d12 * d12;
  const double v = (d22 * dp1 - d12 * dp2) / denominator, w = (d11 * dp2 - d12 * dp1) / denominator;
  return Vec3(1.0 - v - w, v, w);
}

// Whether the triangle's feature nearest `point` (mesh frame, on or by the
// triangle) lies on the smooth part of the mesh (its face, an inactive edge,
// or a corner whose two edges are both inactive), and which.
// The feature, or None where it is an active edge or corner.
CorrectedFeature smoothFeature(const SourceTriangle& triangle, const Vec3& point) {
  const Vec3 coordinates = barycentric(triangle, point);
  int onCount = 0, off = 0, on = 0;
  for (int i = 0; i < 3; ++i) {
    if (coordinates[i] <= onFeatureTolerance) {
      ++onCount;
      on = i;
    } else {
      off = i;
    }
  }
  if (onCount == 0) return CorrectedFeature::Face;
  if (onCount == 1) {  // the edge opposite corner `on`
    const int edge = (on + 1) % 3;
    return triangle.edgeActive(edge) ? CorrectedFeature::None : static_cast<CorrectedFeature>(edge);
  }
  // The corner `off`, between its two edges.
  if (triangle.edgeActive(off) || triangle.edgeActive((off + 2) % 3)) return CorrectedFeature::None;
  return static_cast<CorrectedFeature>(3 + off);
}

// The answer with the face normal: the convex shape's deepest point below
// the face's plane, on the side its centre is.
ContactResult alongFace(const SourceTriangle& triangle, const Transform& meshPose, const Collider& convex,
                        const Transform& convexPose, const ContactResult& found, double touchingTolerance) {
  const Vec3& faceNormal = triangle.normal;
  const Vec3& corner = triangle.corners[0];
  const double centreSide = (meshPose.applyInverse(convexPose.position) - corner).dot(faceNormal);
  const double normalSide = (meshPose.rotation.conjugate() * found.normal).dot(faceNormal);
  const double side = centreSide != 0.0 ? centreSide : normalSide;
  const Vec3 normal = meshPose.rotation * (side >= 0.0 ? faceNormal : Vec3(-faceNormal));
  const Vec3 deepest = convex.support(convexPose, -normal);
  const double separation = (deepest - meshPose.apply(corner)).dot(normal);
  ContactResult result = classifyContact(separation, normal, deepest - separation * normal, deepest, touchingTolerance);
  result.gjkIterations = found.gjkIterations;
  result.epaIterations = found.epaIterations;
  result.usedGeneralPath = found.usedGeneralPath;
  return result;
}

double signedDistance(const ContactResult& result) {
  return result.status == ContactStatus::Separated ? result.distance : -result.depth;
}

// A contact given the face normal is measured against the face's plane,
// which runs on past the triangle: its points that land beyond the triangle
// belong to the neighbour across the edge (which finds them itself) and are
// dropped here. The clipped points of a face lie on it; the single point of
// a shape that clips to nothing (a sphere, or a box over the neighbour) may not.
void keepOnTriangle(const SourceTriangle& triangle, const Transform& meshPose, bool meshIsA,
                    ContactManifold& manifold) {
  int kept = 0;
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    const Vec3 coordinates = barycentric(triangle, meshPose.applyInverse(meshIsA ? point.pointA : point.pointB));
    if ((coordinates.array() >= -onFeatureTolerance).all())
      manifold.points[kept++] = point;
  }
  manifold.pointCount = kept;
}

// Points of one merged manifold that name the same place twice (a sphere
// over a seam is found by both triangles) are kept once.
void dropRepeats(std::vector<ManifoldPoint>& points, double tolerance) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool repeat = false;
    for (std::size_t j = 0; j < kept && !repeat; ++j)
      repeat = (points[j].pointA - points[i].pointA).norm() <= tolerance &&
               (points[j].pointB - points[i].pointB).norm() <= tolerance;
    if (!repeat) points[kept++] = points[i];
  }
  points.resize(kept);
}

// Keeps the points at the corners of the merged patch's outline, in their
// order: each triangle's clipped polygon adds points along the seams that
// lie inside or on the edge of the whole patch and hold nothing the corners
// do not. The deepest point is a corner: the points share one plane (the
// incident face), so their separation is linear over the patch.
void keepOutline(std::vector<ManifoldPoint>& points, const Vec3& normal) {
  if (points.size() <= 3) return;
  const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto at = [&](std::size_t i) { return Eigen::Vector2d(points[i].pointB.dot(u), points[i].pointB.dot(v)); };
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const Eigen::Vector2d p = at(i), q = at(j);
    return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y() || (p.y() == q.y() && i < j)));
  });
  double spread = 0.0;
  for (const std::size_t i : order) spread = std::max(spread, (at(i) - at(order[0])).norm());
  const double turnTolerance = 1e-9 * spread * spread;
  const auto turn = [&](std::size_t o, std::size_t p, std::size_t q) {
    const Eigen::Vector2d a = at(p) - at(o), b = at(q) - at(o);
    return a.x() * b.y() - a.y() * b.x();
  };
  std::vector<std::size_t> hull;
  for (int pass = 0; pass < 2; ++pass) {  // lower chain, then upper
    const std::size_t start = hull.size();
    for (std::size_t k = 0; k < order.size(); ++k) {
      const std::size_t i = pass == 0 ? order[k] : order[order.size() - 1 - k];
      while (hull.size() >= start + 2 && turn(hull[hull.size() - 2], hull.back(), i) <= turnTolerance) hull.pop_back();
      hull.push_back(i);
    }
    hull.pop_back();  // the chain's last point starts the other
  }
  std::sort(hull.begin(), hull.end());
  hull.erase(std::unique(hull.begin(), hull.end()), hull.end());
  if (hull.size() < 3) return;  // all in a line: keep them, reduceToFour picks the ends
  std::vector<ManifoldPoint> outline;
  outline.reserve(hull.size());
  for (const std::size_t i : hull) outline.push_back(points[i]);
  points = std::move(outline);
}

// Manifolds of one pair whose normals agree become one: the first's normal,
// every point's separation measured along it, repeats dropped, the patch's
// outline kept and cut down to four.
void mergeByNormal(MeshContactScratch& scratch, std::vector<ContactManifold>& out) {
  const double cosMerge = std::cos(meshMergeAngle);
  std::vector<ContactManifold>& found = scratch.found;
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (found[i].pointCount == 0) continue;
    const Vec3 normal = found[i].normal;
    std::vector<ManifoldPoint>& merged = scratch.merged;
    merged.assign(found[i].points.begin(), found[i].points.begin() + found[i].pointCount);
    bool several = false;
    double size = 0.0;
    for (std::size_t j = i + 1; j < found.size(); ++j) {
      if (found[j].pointCount == 0 || found[j].normal.dot(normal) < cosMerge) continue;
      for (int p = 0; p < found[j].pointCount; ++p) {
        ManifoldPoint point = found[j].points[p];
        point.separation = (point.pointB - point.pointA).dot(normal);
        merged.push_back(point);
      }
      found[j].pointCount = 0;
      several = true;
    }
    ContactManifold& manifold = out.emplace_back(found[i]);
    if (several) {
      for (const ManifoldPoint& point : merged) size = std::max(size, point.pointB.cwiseAbs().maxCoeff());
      dropRepeats(merged, 1e-12 * (1.0 + size));
      keepOutline(merged, normal);
      if (merged.size() <= static_cast<std::size_t>(ContactManifold::maxPoints)) {
        manifold.pointCount = 0;
        for (const ManifoldPoint& point : merged) manifold.points[manifold.pointCount++] = point;
      } else {
        reduceToFour(manifold, merged);
      }
    }
    // One order whatever triangles the points came from, so a body sliding
    // across seams keeps its points in place in the manifold.
    std::stable_sort(manifold.points.begin(), manifold.points.begin() + manifold.pointCount,
                     [](const ManifoldPoint& p, const ManifoldPoint& q) { return p.featureId < q.featureId; });
  }
}

}  // namespace

ContactResult collideWithTriangle(const SourceTriangle& triangle, const Transform& meshPose, const Collider& convex,
                                  const Transform& convexPose, const NarrowPhaseOptions& options, double reach,
                                  CorrectedFeature* corrected, ContactResult* uncorrected) {
  const TriangleCollider shape = triangle.collider();
  ContactResult result =
      convex.kind() == ColliderKind::Sphere
          ? sphereTriangle(shape, meshPose, static_cast<const SphereCollider&>(convex), convexPose.position,
                           options.touchingTolerance)
          : collide(shape, meshPose, convex, convexPose, options);
  if (corrected) *corrected = CorrectedFeature::None;
  if (uncorrected) *uncorrected = result;
  if (signedDistance(result) > reach) return result;
  const double alongNormal = (meshPose.rotation.conjugate() * result.normal).dot(triangle.normal);
  if (std::abs(alongNormal) >= std::cos(meshMergeAngle)) return result;
  const CorrectedFeature feature = smoothFeature(triangle, meshPose.applyInverse(result.pointA));
  if (feature == CorrectedFeature::None) return result;
  if (corrected) *corrected = feature;
  return alongFace(triangle, meshPose, convex, convexPose, result, options.touchingTolerance);
}

ContactResult collideWithMesh(const TriangleSource& mesh, const Transform& meshPose, const Collider& convex,
                              const Transform& convexPose, bool meshIsA, std::uint32_t a, std::uint32_t b,
                              double reach, const NarrowPhaseOptions& options, MeshContactScratch& scratch,
                              std::vector<ContactManifold>& out, MeshContactCounts& counts,
                              std::vector<MeshTriangleTest>* tested) {
  const Quat toMesh = meshPose.rotation.conjugate();
  const Transform relative{toMesh * (convexPose.position - meshPose.position), (toMesh * convexPose.rotation).normalized()};
  scratch.triangles.clear();
  mesh.query(convex.worldBounds(relative).enlarged(reach), scratch.triangles);
  scratch.found.clear();
  ContactResult deepest;
  deepest.distance = std::numeric_limits<double>::infinity();
  double deepestDistance = deepest.distance;
  // The nearest contact that took the face normal and then lay off its
  // triangle: where every triangle's was (a ball on a convex peak whose
  // edges are too gentle to be active, each face's plane passing under the
  // ball beside its own face), the peak's own contact is taken instead.
  double droppedDistance = std::numeric_limits<double>::infinity();
  ContactResult dropped;
  std::uint32_t droppedTriangle = 0;
  for (const std::uint32_t t : scratch.triangles) {
    ++counts.triangles;
    CorrectedFeature feature = CorrectedFeature::None;
    const SourceTriangle source = mesh.triangleAt(t);
    ContactResult uncorrected;
    ContactResult result =
        collideWithTriangle(source, meshPose, convex, convexPose, options, reach, &feature, &uncorrected);
    if (tested) tested->push_back({t, feature});
    const double distance = signedDistance(result);
    if (distance > reach) continue;
    const bool corrected = feature != CorrectedFeature::None;
    counts.corrected += corrected ? 1 : 0;
    if (!meshIsA) result = swapped(result);
    ContactManifold& manifold = scratch.found.emplace_back();
    manifold.a = a;
    manifold.b = b;
    const TriangleCollider triangle = source.collider();
    if (meshIsA) buildGeneralManifold(triangle, meshPose, convex, convexPose, result, reach, scratch.manifold, manifold);
    else buildGeneralManifold(convex, convexPose, triangle, meshPose, result, reach, scratch.manifold, manifold);
    if (corrected) keepOnTriangle(source, meshPose, meshIsA, manifold);
    if (manifold.pointCount == 0) {
      scratch.found.pop_back();
      if (corrected && signedDistance(uncorrected) < droppedDistance) {
        droppedDistance = signedDistance(uncorrected);
        dropped = meshIsA ? uncorrected : swapped(uncorrected);
        droppedTriangle = t;
      }
      continue;
    }
    if (distance < deepestDistance) {
      deepestDistance = distance;
      deepest = result;
    }
  }
  if (scratch.found.empty() && droppedDistance <= reach) {
    ContactManifold& manifold = scratch.found.emplace_back();
    manifold.a = a;
    manifold.b = b;
    const TriangleCollider triangle = mesh.triangleAt(droppedTriangle).collider();
    if (meshIsA) buildGeneralManifold(triangle, meshPose, convex, convexPose, dropped, reach, scratch.manifold, manifold);
    else buildGeneralManifold(convex, convexPose, triangle, meshPose, dropped, reach, scratch.manifold, manifold);
    if (manifold.pointCount == 0) scratch.found.pop_back();
    else deepest = dropped;
  }
  mergeByNormal(scratch, out);
  return deepest;
}

}  // namespace physdbg
