#include "engine/narrowphase/epa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace physdbg {
namespace {

constexpr int kVertexCapacity = kEpaFaceCapacity / 2 + 4;

// An oriented edge packed in one word (from in the high half), so finding an
// edge's reverse among the removed ones is a scan of plain integers.
using Edge = std::uint64_t;

Edge makeEdge(int from, int to) {
  return static_cast<Edge>(static_cast<std::uint32_t>(from)) << 32 | static_cast<std::uint32_t>(to);
}
Edge reversed(Edge edge) { return edge << 32 | edge >> 32; }
int edgeFrom(Edge edge) { return static_cast<int>(edge >> 32); }
int edgeTo(Edge edge) { return static_cast<int>(edge & 0xffffffffu); }

struct Face {
  std::array<int, 3> v;
  Vec3 normal;
  double distance;  // signed distance of the origin's projection; +inf when degenerate
};

struct Polytope {
  std::array<SimplexVertex, kVertexCapacity> vertices;
  std::array<Face, kEpaFaceCapacity> faces;
  int vertexCount = 0;
  int faceCount = 0;

  void addFace(int i, int j, int k) {
    const Vec3& p = vertices[i].w;
    const Vec3 n = (vertices[j].w - p).cross(vertices[k].w - p);
    const double length = n.norm();
    if (length == 0.0) {
      faces[faceCount++] = {{i, j, k}, Vec3::Zero(), std::numeric_limits<double>::infinity()};
      return;
    }
    const Vec3 unit = n / length;
    faces[faceCount++] = {{i, j, k}, unit, unit.dot(p)};
  }

  int closestFace() const {
    int best = -1;
    for (int f = 0; f < faceCount; ++f) {
      if (best < 0 || faces[f].distance < faces[best].distance) best = f;
    }
    return best;
  }
};

// Distance from w to the affine hull of the accepted points (0, 1, 2 or 3 of them).
double offHullDistance(const std::array<SimplexVertex, 4>& points, int count, const Vec3& w) {
  if (count == 0) return std::numeric_limits<double>::infinity();
  const Vec3 d = w - points[0].w;
  if (count == 1) return d.norm();
  const Vec3 e = points[1].w - points[0].w;
  if (count == 2) return d.cross(e).norm() / e.norm();
  const Vec3 n = e.cross(points[2].w - points[0].w).normalized();
  return std::abs(n.dot(d));
}

// Directions that can reach past the affine hull of `count` points.
int growthDirections(const std::array<SimplexVertex, 4>& points, int count, std::array<Vec3, 6>& out) {
  if (count <= 1) {
    out = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
    return 6;
  }
  const Vec3 e = (points[1].w - points[0].w).normalized();
  if (count == 2) {
    Vec3 axis = Vec3::Zero();
    int smallest = 0;
    e.cwiseAbs().minCoeff(&smallest);
    axis[smallest] = 1.0;
    const Vec3 u = e.cross(axis).normalized();
    const Vec3 v = e.cross(u);
    out = {u, -u, v, -v, (u + v).normalized(), -(u + v).normalized()};
    return 6;
  }
  const Vec3 n = e.cross(points[2].w - points[0].w).normalized();
  out[0] = n;
  out[1] = -n;
  return 2;
}

// A full-volume tetrahedron from the simplex plus extra supports, or fewer
// than 4 points when A - B is flat.
int buildTetrahedron(const Simplex& start, SupportShape& a, SupportShape& b, double eps,
                     std::array<SimplexVertex, 4>& points) {
  int count = 0;
  for (int i = 0; i < start.size; ++i) {
    if (offHullDistance(points, count, start.vertices[i].w) > eps) points[count++] = start.vertices[i];
  }
  while (count < 4) {
    std::array<Vec3, 6> directions;
    const int available = growthDirections(points, count, directions);
    double bestDistance = eps;
    SimplexVertex best{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (int d = 0; d < available; ++d) {
      const SimplexVertex candidate = supportOfDifference(a, b, directions[d]);
      const double distance = offHullDistance(points, count, candidate.w);
      if (distance > bestDistance) bestDistance = distance, best = candidate;
    }
    if (bestDistance <= eps) return count;
    points[count++] = best;
  }
  return count;
}

void initialisePolytope(Polytope& polytope, const std::array<SimplexVertex, 4>& points) {
  for (int i = 0; i < 4; ++i) polytope.vertices[i] = points[i];
  polytope.vertexCount = 4;
  const Vec3 inside = 0.25 * (points[0].w + points[1].w + points[2].w + points[3].w);
  constexpr std::array<std::array<int, 3>, 4> faces{{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  const bool flip = (points[1].w - points[0].w).cross(points[2].w - points[0].w).dot(inside - points[0].w) > 0.0;
  for (const auto& [i, j, k] : faces) {
    if (flip) {
      polytope.addFace(i, k, j);
    } else {
      polytope.addFace(i, j, k);
    }
  }
}

// Removes every face that sees w and closes the horizon to it. Returns the
// face closest to the origin afterwards (found in the same passes), or -1
// when the budget leaves no room.
int expand(Polytope& polytope, const SimplexVertex& vertex, int faceBudget, double eps) {
  std::array<Edge, kEpaFaceCapacity> removed;  // left uninitialised: filled before use
  int removedCount = 0;
  int live = 0;  // faces that stay are compacted in the same pass
  int closest = -1;  // the first face of least distance, as a scan would find
  double closestDistance = 0.0;
  const auto consider = [&](int f) {
    if (closest < 0 || polytope.faces[f].distance < closestDistance)
      closest = f, closestDistance = polytope.faces[f].distance;
  };
  for (int f = 0; f < polytope.faceCount; ++f) {
    const Face& face = polytope.faces[f];
    if (face.normal.dot(vertex.w - polytope.vertices[face.v[0]].w) <= eps) {
      if (live != f) polytope.faces[live] = face;
      consider(live++);
      continue;
    }
    if (removedCount + 3 > kEpaFaceCapacity) return -1;
    for (int e = 0; e < 3; ++e) removed[removedCount++] = makeEdge(face.v[e], face.v[(e + 1) % 3]);
  }
  polytope.faceCount = live;
  std::array<Edge, kEpaFaceCapacity> horizon;
  int horizonCount = 0;
  for (int e = 0; e < removedCount; ++e) {
    const Edge reverse = reversed(removed[e]);
    if (std::find(removed.begin(), removed.begin() + removedCount, reverse) == removed.begin() + removedCount) {
      horizon[horizonCount++] = removed[e];
    }
  }
  const int newIndex = polytope.vertexCount;
  if (live + horizonCount > std::min(faceBudget, kEpaFaceCapacity) || newIndex >= kVertexCapacity) return -1;
  polytope.vertices[polytope.vertexCount++] = vertex;
  for (int e = 0; e < horizonCount; ++e) {
    polytope.addFace(edgeFrom(horizon[e]), edgeTo(horizon[e]), newIndex);
    consider(polytope.faceCount - 1);
  }
  return closest;
}

EpaResult contactFromFace(const Polytope& polytope, const Face& face) {
  const Vec3& a = polytope.vertices[face.v[0]].w;
  const Vec3 e0 = polytope.vertices[face.v[1]].w - a, e1 = polytope.vertices[face.v[2]].w - a;
  const Vec3 p = face.normal * face.distance - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = p.dot(e0), d21 = p.dot(e1);
  const double denominator = d00 * d11 - d01 * d01;
  double v = 1.0 / 3.0, w = 1.0 / 3.0;
  if (denominator > 0.0) {
    v = (d11 * d20 - d01 * d21) / denominator;
    w = (d00 * d21 - d01 * d20) / denominator;
  }
  const std::array<double, 3> weights{1.0 - v - w, v, w};
  EpaResult result;
  result.normal = face.normal;
  result.depth = face.distance;
  result.pointA = Vec3::Zero();
  result.pointB = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    result.pointA += weights[i] * polytope.vertices[face.v[i]].a;
    result.pointB += weights[i] * polytope.vertices[face.v[i]].b;
  }
  return result;
}

}  // namespace

EpaResult runEpa(const Simplex& start, SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options) {
  const double size = pairSize(a, b);
  const double eps = 1e-10 * size;
  std::array<SimplexVertex, 4> points{};
  const int count = buildTetrahedron(start, a, b, eps, points);
  EpaResult result;
  if (count < 4) {  // A - B is flat: the shapes can only touch
    if (count >= 3) result.normal = (points[1].w - points[0].w).cross(points[2].w - points[0].w).normalized();
    // GJK stopped on the origin, so its weights give the touching points.
    result.pointA = start.size > 0 ? start.pointA() : a.centre();
    result.pointB = start.size > 0 ? start.pointB() : b.centre();
    return result;
  }
  Polytope polytope;
  initialisePolytope(polytope, points);
  const double tolerance = std::max(options.relativeTolerance * size, 1e-15 * size);
  int closest = polytope.closestFace();
  while (true) {
    ++result.iterations;
    const Face& face = polytope.faces[closest];
    const SimplexVertex vertex = supportOfDifference(a, b, face.normal);
    if (face.normal.dot(vertex.w) - face.distance <= tolerance) break;
    const Face kept = face;
    const int next = expand(polytope, vertex, options.maxEpaFaces, 1e-14 * size);
    if (next < 0 || !std::isfinite(polytope.faces[next].distance)) {  // budget spent, or no face left
      polytope.faces[0] = kept;
      polytope.faceCount = 1;
      closest = 0;
      break;
    }
    closest = next;
  }
  const EpaResult contact = contactFromFace(polytope, polytope.faces[closest]);
  return {contact.normal, contact.depth, contact.pointA, contact.pointB, result.iterations};
}

}  // namespace physdbg
