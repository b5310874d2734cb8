#include "engine/colliders/convex_mesh_collider.h"

#include <cmath>

namespace physdbg {
namespace {

constexpr int kBruteForceVertexCount = 16;

// Six axis directions, then the eight cube diagonals.
Vec3 seedDirection(int s) {
  if (s < 6) return Vec3::Unit(s / 2) * (s % 2 == 0 ? 1.0 : -1.0);
  const int d = s - 6;
  return Vec3(d & 1 ? 1.0 : -1.0, d & 2 ? 1.0 : -1.0, d & 4 ? 1.0 : -1.0);
}

// Covariance of a tetrahedron with one vertex at the origin (unit density).
Mat3 tetrahedronCovariance(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mat3 edges;
  edges << a, b, c;
  Mat3 canonical;
  canonical << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  return edges.determinant() / 120.0 * edges * canonical * edges.transpose();
}

struct MassProperties {
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Mat3 unitInertia = Mat3::Zero();
};

// Mass properties from tetrahedra fanned from a point inside the hull, which
// keeps every term small and well conditioned, in units of a power of two
// near the hull's size (exact), so that no product of three coordinates
// under- or overflows however small or large the hull is.
MassProperties massProperties(const ConvexHull& hull, const Aabb& bounds) {
  const auto& v = hull.vertices;
  Vec3 reference = Vec3::Zero();
  for (const Vec3& p : v) reference += p / static_cast<double>(v.size());
  int exponent = 0;
  std::frexp(bounds.halfExtents().maxCoeff(), &exponent);
  const auto scaled = [](int power) { return [power](double x) { return std::ldexp(x, power); }; };
  double volume = 0.0;
  Mat3 covariance = Mat3::Zero();
  Vec3 moment = Vec3::Zero();
  for (const auto& t : hull.triangles) {
    const Vec3 a = (v[t[0]] - reference).unaryExpr(scaled(-exponent));
    const Vec3 b = (v[t[1]] - reference).unaryExpr(scaled(-exponent));
    const Vec3 c = (v[t[2]] - reference).unaryExpr(scaled(-exponent));
    const double tetraVolume = a.dot(b.cross(c)) / 6.0;
    volume += tetraVolume;
    moment += tetraVolume * (a + b + c) / 4.0;
    covariance += tetrahedronCovariance(a, b, c);
  }
  const Vec3 offset = moment / volume;
  covariance -= volume * offset * offset.transpose();
  const Mat3 unitInertia = (Mat3::Identity() * covariance.trace() - covariance) / volume;
  return {std::ldexp(volume, 3 * exponent), reference + offset.unaryExpr(scaled(exponent)),
          unitInertia.unaryExpr(scaled(2 * exponent))};
}

}  // namespace

ConvexMeshCollider::ConvexMeshCollider(std::vector<Vec3> points) : hull_(buildConvexHull(points)) {
  const auto& v = hull_.vertices;
  bounds_ = {v.front(), v.front()};
  for (const Vec3& p : v) bounds_ = {bounds_.min.cwiseMin(p), bounds_.max.cwiseMax(p)};
  for (int s = 0; s < static_cast<int>(seedVertices_.size()); ++s) {
    const Vec3 direction = seedDirection(s);
    for (int i = 0; i < static_cast<int>(v.size()); ++i) {
      if (v[i].dot(direction) > v[seedVertices_[s]].dot(direction)) seedVertices_[s] = i;
    }
  }
  const MassProperties mass = massProperties(hull_, bounds_);
  volume_ = mass.volume;
  centroid_ = mass.centroid;
  unitInertia_ = mass.unitInertia;
}

int ConvexMeshCollider::supportIndex(const Vec3& direction, int hint) const {
  const auto& v = hull_.vertices;
  const int count = static_cast<int>(v.size());
  if (count <= kBruteForceVertexCount) {
    int best = 0;
    for (int i = 1; i < count; ++i) {
      if (v[i].dot(direction) > v[best].dot(direction)) best = i;
    }
    return best;
  }
  // Candidates: the hint, the extreme vertex of the dominant axis and that of
  // the direction's octant diagonal.
  int axis = 0;
  direction.cwiseAbs().maxCoeff(&axis);
  const int axisSeed = seedVertices_[2 * axis + (direction[axis] < 0.0 ? 1 : 0)];
  const int octant = (direction.x() >= 0.0 ? 1 : 0) | (direction.y() >= 0.0 ? 2 : 0) | (direction.z() >= 0.0 ? 4 : 0);
  int start = seedVertices_[6 + octant];
  double best = v[start].dot(direction);
  for (int candidate : {axisSeed, hint}) {
    if (candidate < 0 || candidate >= count) continue;
    const double value = v[candidate].dot(direction);
    if (value > best) best = value, start = candidate;
  }
  return climb(direction, start);
}

int ConvexMeshCollider::climb(const Vec3& direction, int start) const {
  const auto& v = hull_.vertices;
  int current = start;
  double best = v[current].dot(direction);
  for (int previous = -1; previous != current;) {
    previous = current;
    for (int k = hull_.neighbourStart[previous]; k < hull_.neighbourStart[previous + 1]; ++k) {
      const double value = hull_.neighbourPoints[k].dot(direction);
      if (value > best) best = value, current = hull_.neighbours[k];
    }
  }
  return current;
}

}  // namespace physdbg
