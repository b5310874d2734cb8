#include "engine/colliders/convex_mesh_collider.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace physdbg {
namespace {

constexpr int kBruteForceVertexCount = 16;
// Plateau vertices walked before giving up for a linear scan (a face seen
// head-on with more corners than this, or a zero direction).
constexpr int kPlateauCapacity = 64;
// Bands (bandScale_ * |d|_1) outside these come from directions whose p . d
// may under- or overflow, where no margin can be trusted.
constexpr double kLeastTrustedBand = 1e-280;
constexpr double kGreatestTrustedBand = 1e280;

// p . d written out, so every caller rounds it alike; the climb and the
// scan must agree to the last bit.
double along(const Vec3& p, const Vec3& d) { return p.x() * d.x() + p.y() * d.y() + p.z() * d.z(); }

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
  bandScale_ = 32.0 * DBL_EPSILON * std::max(bounds_.min.cwiseAbs().maxCoeff(), bounds_.max.cwiseAbs().maxCoeff());
  // Each cell climbs from the one before, a nearby direction (the climb is
  // exact from any start), so the table costs a few climbing steps a cell
  // rather than a scan of the hull.
  if (static_cast<int>(v.size()) > kBruteForceVertexCount) {
    startMap_ = SupportCubeMap(static_cast<int>(v.size()));
    int previous = 0;
    for (int cell = 0; cell < startMap_.cellCount(); ++cell) {
      const Vec3 direction = startMap_.cellCentre(cell);
      previous = climb(direction, previous, bandScale_ * direction.lpNorm<1>());
      startMap_.assign(hull_, cell, previous, bandScale_);
    }
  }
  const MassProperties mass = massProperties(hull_, bounds_);
  volume_ = mass.volume;
  centroid_ = mass.centroid;
  unitInertia_ = mass.unitInertia;
}

int ConvexMeshCollider::scan(const Vec3& direction) const {
  const auto& v = hull_.vertices;
  int best = 0;
  double top = along(v[0], direction);
  for (int i = 1; i < static_cast<int>(v.size()); ++i) {
    const double value = along(v[i], direction);
    if (value > top) top = value, best = i;
  }
  return best;
}

int ConvexMeshCollider::supportIndex(const Vec3& direction, int hint) const {
  const auto& v = hull_.vertices;
  const int count = static_cast<int>(v.size());
  const double length = std::abs(direction.x()) + std::abs(direction.y()) + std::abs(direction.z());
  // A direction with a NaN or an infinity has no climb to speak of.
  if (count <= kBruteForceVertexCount || !(length <= DBL_MAX)) return scan(direction);
  const double band = bandScale_ * length;
  // Zero, tiny and huge directions climb from the hint or vertex 0: the
  // cell lists' margins assume p . d neither under- nor overflows.
  if (!(band >= kLeastTrustedBand && band <= kGreatestTrustedBand)) {
    return climb(direction, hint >= 0 && hint < count ? hint : 0, band);
  }
  const SupportCubeMap::Entry entry = startMap_.lookup(direction);
  if (entry.count > 0) return bestListed(direction, entry);
  // Otherwise start from the better of the hint and the answer at the
  // centre of the direction's cell, which is usually one step away.
  int start = entry.vertices[0];
  if (hint >= 0 && hint < count && hint != start && along(v[hint], direction) > along(v[start], direction)) {
    start = hint;
  }
  return climb(direction, start, band);
}

// The listed vertices are ascending, so a strict comparison keeps the
// lowest index of several tied ones, as the scan does.
int ConvexMeshCollider::bestListed(const Vec3& direction, const SupportCubeMap::Entry& entry) const {
  const auto& v = hull_.vertices;
  int best = entry.vertices[0];
  double top = along(v[best], direction);
  const auto weigh = [&](int i) {
    const int vertex = entry.vertices[i];
    const double value = along(v[vertex], direction);
    if (value > top) top = value, best = vertex;
  };
  // The padded entries first, unrolled: how long a list is is a coin toss.
  static_assert(SupportCubeMap::kPaddedCount == 4);
  weigh(1), weigh(2), weigh(3);
  for (int i = SupportCubeMap::kPaddedCount; i < entry.count; ++i) weigh(i);
  return best;
}

// Steepest ascent to a vertex no neighbour beats. Rounding can leave a tied
// vertex (same face) above or below by a few ulps, so when a neighbour of
// the top is within `band` of it, the plateau is settled exactly: each p . d
// is within 3.5 ulps of sum |p_i d_i| <= largest coordinate * |d|_1 of its
// exact value, and the hull is exactly convex on points within half an ulp
// of the vertices, so 32 ulps of that covers both, four times over.
int ConvexMeshCollider::climb(const Vec3& direction, int start, double band) const {
  int current = start;
  double best = along(hull_.vertices[current], direction);
  while (true) {
    int next = current;
    double nextValue = best;
    bool tied = false;
    const double floor = best - band;
    for (int k = hull_.neighbourStart[current]; k < hull_.neighbourStart[current + 1]; ++k) {
      const double value = along(hull_.neighbourPoints[k], direction);
      if (value < floor) continue;  // most neighbours: one test, as a plain climb
      if (value > nextValue) {
        nextValue = value, next = hull_.neighbours[k];
      } else {
        tied = true;  // within the band of the best so far; matters only at the top
      }
    }
    if (next == current) return tied ? settlePlateau(direction, current, floor) : current;
    current = next;
    best = nextValue;
  }
}

// On an exactly convex hull the vertices above any level are connected, so
// every vertex that can be the scan's answer (within the band of the climb's
// top) is reached from it through vertices above best - band. Among them the
// largest p . d wins, then the lowest index: the linear scan's rule.
int ConvexMeshCollider::settlePlateau(const Vec3& direction, int top, double floor) const {
  std::array<int, kPlateauCapacity> reached;
  int reachedCount = 0;
  reached[reachedCount++] = top;
  int best = top;
  double bestValue = along(hull_.vertices[top], direction);
  for (int i = 0; i < reachedCount; ++i) {
    const int vertex = reached[i];
    for (int k = hull_.neighbourStart[vertex]; k < hull_.neighbourStart[vertex + 1]; ++k) {
      const double value = along(hull_.neighbourPoints[k], direction);
      const int neighbour = hull_.neighbours[k];
      if (!(value >= floor) || std::find(reached.begin(), reached.begin() + reachedCount, neighbour) !=
                                   reached.begin() + reachedCount) {
        continue;
      }
      if (reachedCount == kPlateauCapacity) return scan(direction);
      reached[reachedCount++] = neighbour;
      if (value > bestValue || (value == bestValue && neighbour < best)) best = neighbour, bestValue = value;
    }
  }
  return best;
}

}  // namespace physdbg
