#include "engine/narrowphase/epa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace physdbg {
namespace {

constexpr int kVertexCapacity = kEpaFaceCapacity / 2 + 4;

// A face's edge e runs from v[e] to v[(e + 1) % 3]. Its neighbour across
// that edge is stored as 4 * face + (the neighbour's own edge index), so
// the visible region is found by walking from face to face rather than by
// testing every face, and its border comes out as an ordered loop.
struct Face {
  Vec3 normal;
  std::array<int, 3> v;
  std::array<int, 3> across;
  bool live;
};

struct HorizonEdge {
  int from, to;
  int outside;  // 4 * face + edge of the face that stays, across this edge
};

struct Polytope {
  std::array<SimplexVertex, kVertexCapacity> vertices;
  std::array<Face, kEpaFaceCapacity> faces;
  // Signed distance of the origin's projection per face slot, apart from the
  // faces so the closest-face scan reads one contiguous row; +inf for a
  // degenerate face and for a free slot.
  std::array<double, kEpaFaceCapacity> distances;
  std::array<int, kEpaFaceCapacity> freeSlots;  // slots of removed faces, reused first
  int vertexCount = 0;
  int slotCount = 0;  // slots ever used: [0, slotCount) holds live and free ones
  int freeCount = 0;
  int liveCount = 0;

  int takeSlot() { return freeCount > 0 ? freeSlots[--freeCount] : slotCount++; }
  int capacityLeft() const { return kEpaFaceCapacity - slotCount + freeCount; }

  void setFace(int slot, int i, int j, int k) {
    Face& face = faces[slot];
    face.v = {i, j, k};
    face.live = true;
    ++liveCount;
    const Vec3& p = vertices[i].w;
    const Vec3 n = (vertices[j].w - p).cross(vertices[k].w - p);
    const double length = n.norm();
    if (length == 0.0) {
      face.normal = Vec3::Zero();
      distances[slot] = std::numeric_limits<double>::infinity();
      return;
    }
    face.normal = n / length;
    distances[slot] = face.normal.dot(p);
  }

  // A slot left unrecycled keeps its face's data until recycle() is called.
  void removeFace(int slot, bool recycleNow = true) {
    faces[slot].live = false;
    distances[slot] = std::numeric_limits<double>::infinity();
    if (recycleNow) recycle(slot);
    --liveCount;
  }
  void recycle(int slot) { freeSlots[freeCount++] = slot; }

  void link(int faceA, int edgeA, int faceB, int edgeB) {
    faces[faceA].across[edgeA] = 4 * faceB + edgeB;
    faces[faceB].across[edgeB] = 4 * faceA + edgeA;
  }

  // The first live slot of least distance, or -1 when every face is degenerate.
  int closestFace() const {
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int f = 0; f < slotCount; ++f) {
      if (distances[f] < bestDistance) best = f, bestDistance = distances[f];
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

// The starting tetrahedron's faces in both orientations, with each edge's
// neighbour (the face that runs it the other way), worked out at compile time.
struct Tetrahedron {
  std::array<std::array<int, 3>, 4> faces;
  std::array<std::array<int, 3>, 4> across;
};

constexpr Tetrahedron tetrahedron(bool flip) {
  Tetrahedron t{{{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}}, {}};
  if (flip) {
    for (auto& face : t.faces) std::swap(face[1], face[2]);
  }
  for (int f = 0; f < 4; ++f) {
    for (int e = 0; e < 3; ++e) {
      for (int g = 0; g < 4; ++g) {
        for (int m = 0; m < 3; ++m) {
          if (t.faces[g][m] == t.faces[f][(e + 1) % 3] && t.faces[g][(m + 1) % 3] == t.faces[f][e]) {
            t.across[f][e] = 4 * g + m;
          }
        }
      }
    }
  }
  return t;
}

constexpr std::array<Tetrahedron, 2> kTetrahedra{tetrahedron(false), tetrahedron(true)};

void initialisePolytope(Polytope& polytope, const std::array<SimplexVertex, 4>& points) {
  for (int i = 0; i < 4; ++i) polytope.vertices[i] = points[i];
  polytope.vertexCount = 4;
  const Vec3 inside = 0.25 * (points[0].w + points[1].w + points[2].w + points[3].w);
  const bool flip = (points[1].w - points[0].w).cross(points[2].w - points[0].w).dot(inside - points[0].w) > 0.0;
  const Tetrahedron& t = kTetrahedra[flip ? 1 : 0];
  polytope.slotCount = 4;
  for (int f = 0; f < 4; ++f) {
    polytope.setFace(f, t.faces[f][0], t.faces[f][1], t.faces[f][2]);
    polytope.faces[f].across = t.across[f];
  }
}

bool sees(const Polytope& polytope, int slot, const Vec3& w, double eps) {
  const Face& face = polytope.faces[slot];
  return face.normal.dot(w - polytope.vertices[face.v[0]].w) > eps;
}

// Removes the faces that see w and are connected to `first` (which does)
// through faces that see it, and lists the border of that region in order,
// each edge as the removed face ran it. Returns false when the border is
// not one closed loop (rounding can make the seen region pinched or holed).
bool removeSeenRegion(Polytope& polytope, int first, const Vec3& w, double eps,
                      std::array<HorizonEdge, kEpaFaceCapacity>& horizon, int& horizonCount) {
  struct Step {
    int face;
    int edge;  // next edge of `face` to cross
    int last;  // edge after which `face` is done
  };
  std::array<Step, kEpaFaceCapacity> stack;
  int depth = 0;
  horizonCount = 0;
  polytope.removeFace(first, false);  // the caller's fallback answer until the new faces are in
  stack[depth++] = {first, 0, 3};
  while (depth > 0) {
    Step& step = stack[depth - 1];
    if (step.edge == step.last) {
      --depth;
      continue;
    }
    const int e = step.edge < 3 ? step.edge : step.edge - 3;
    ++step.edge;
    const Face& face = polytope.faces[step.face];
    const int link = face.across[e];
    const int neighbour = link >> 2, neighbourEdge = link & 3;
    if (!polytope.faces[neighbour].live) continue;
    if (sees(polytope, neighbour, w, eps)) {
      polytope.removeFace(neighbour);
      // Enter across neighbourEdge: walk its other two edges, in order.
      stack[depth++] = {neighbour, neighbourEdge + 1, neighbourEdge + 3};
    } else {
      if (horizonCount == kEpaFaceCapacity) return false;
      horizon[horizonCount++] = {face.v[e], face.v[e == 2 ? 0 : e + 1], link};
    }
  }
  for (int h = 0; h < horizonCount; ++h) {
    if (horizon[h].to != horizon[(h + 1) % horizonCount].from) return false;
  }
  return horizonCount >= 3;
}

// Removes the region that sees the new vertex, starting at the closest face
// (which sees it: the caller has checked its gain), and closes the border
// to it. Returns the closest face afterwards, or -1 when the polytope cannot
// grow (the budget, or a border that is not one loop).
int expand(Polytope& polytope, int closest, const SimplexVertex& vertex, int faceBudget, double eps) {
  const int newIndex = polytope.vertexCount;
  if (newIndex >= kVertexCapacity) return -1;
  std::array<HorizonEdge, kEpaFaceCapacity> horizon;  // left uninitialised: filled before use
  int horizonCount = 0;
  if (!removeSeenRegion(polytope, closest, vertex.w, eps, horizon, horizonCount)) return -1;
  if (polytope.liveCount + horizonCount > std::min(faceBudget, kEpaFaceCapacity) ||
      horizonCount > polytope.capacityLeft()) {
    return -1;
  }
  polytope.vertices[polytope.vertexCount++] = vertex;
  std::array<int, kEpaFaceCapacity> added;
  for (int h = 0; h < horizonCount; ++h) {
    const int slot = polytope.takeSlot();
    added[h] = slot;
    polytope.setFace(slot, horizon[h].from, horizon[h].to, newIndex);
    polytope.link(slot, 0, horizon[h].outside >> 2, horizon[h].outside & 3);
  }
  for (int h = 0; h < horizonCount; ++h) polytope.link(added[h], 1, added[(h + 1) % horizonCount], 2);
  polytope.recycle(closest);
  return polytope.closestFace();
}

EpaResult contactFromFace(const Polytope& polytope, int slot) {
  const Face& face = polytope.faces[slot];
  const double distance = polytope.distances[slot];
  const Vec3& a = polytope.vertices[face.v[0]].w;
  const Vec3 e0 = polytope.vertices[face.v[1]].w - a, e1 = polytope.vertices[face.v[2]].w - a;
  const Vec3 p = face.normal * distance - a;
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
  result.depth = distance;
  result.pointA = Vec3::Zero();
  result.pointB = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    result.pointA += weights[i] * polytope.vertices[face.v[i]].a;
    result.pointB += weights[i] * polytope.vertices[face.v[i]].b;
  }
  return result;
}

// A - B has no volume the polytope can use (flat, or faces too small to
// have a normal): the shapes only touch. GJK stopped on the origin, so its
// weights give the touching points.
EpaResult touchingResult(const Simplex& start, const std::array<SimplexVertex, 4>& points, int count,
                         const SupportShape& a, const SupportShape& b) {
  EpaResult result;
  if (count >= 3) {
    const Vec3 normal = (points[1].w - points[0].w).cross(points[2].w - points[0].w);
    if (normal.squaredNorm() > 0.0) result.normal = normal.normalized();
  }
  result.pointA = start.size > 0 ? start.pointA() : a.centre();
  result.pointB = start.size > 0 ? start.pointB() : b.centre();
  return result;
}

}  // namespace

EpaResult runEpa(const Simplex& start, SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options) {
  const double size = pairSize(a, b);
  std::array<SimplexVertex, 4> points{};
  const int count = buildTetrahedron(start, a, b, 1e-10 * size, points);
  if (count < 4) return touchingResult(start, points, count, a, b);
  Polytope polytope;
  initialisePolytope(polytope, points);
  int closest = polytope.closestFace();
  if (closest < 0) return touchingResult(start, points, 3, a, b);
  const double tolerance = std::max(options.relativeTolerance * size, 1e-15 * size);
  // A face sees a point that lies above its plane by more than this; closer
  // than this the point is on the plane within rounding.
  const double seenEps = 1e-14 * size;
  int iterations = 0;
  while (true) {
    ++iterations;
    const Face& face = polytope.faces[closest];
    const SimplexVertex vertex = supportOfDifference(a, b, face.normal);
    const double gain = face.normal.dot(vertex.w) - polytope.distances[closest];
    // A face the new point does not see cannot be expanded: it is the
    // answer even when the tolerance asks for less.
    if (gain <= tolerance || gain <= seenEps) break;
    const double keptDistance = polytope.distances[closest];
    const int next = expand(polytope, closest, vertex, options.maxEpaFaces, seenEps);
    if (next < 0) {  // budget spent, or the polytope cannot grow: report the closest face so far
      // expand() never reuses the expanded face's slot within the call, so it still holds it.
      polytope.distances[closest] = keptDistance;
      break;
    }
    closest = next;
  }
  EpaResult result = contactFromFace(polytope, closest);
  result.iterations = iterations;
  return result;
}

}  // namespace physdbg
