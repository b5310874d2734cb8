#include "engine/narrowphase/simplex.h"

#include <initializer_list>
#include <limits>

namespace physdbg {
namespace {

// Closest point of a sub-simplex: vertex indices into the caller's simplex.
struct Feature {
  int count = 0;
  std::array<int, 4> index{};
  std::array<double, 4> weight{};
  double distanceSquared = 0.0;
};

Feature makeFeature(const Simplex& s, std::initializer_list<std::pair<int, double>> parts) {
  Feature f;
  Vec3 point = Vec3::Zero();
  for (const auto& [i, weight] : parts) {
    f.index[f.count] = i;
    f.weight[f.count++] = weight;
    point += weight * s.vertices[i].w;
  }
  f.distanceSquared = point.squaredNorm();
  return f;
}

Feature closestOnSegment(const Simplex& s, int i, int j) {
  const Vec3& a = s.vertices[i].w;
  const Vec3 ab = s.vertices[j].w - a;
  const double lengthSquared = ab.squaredNorm();
  const double t = lengthSquared > 0.0 ? -a.dot(ab) / lengthSquared : 0.0;
  if (t <= 0.0) return makeFeature(s, {{i, 1.0}});
  if (t >= 1.0) return makeFeature(s, {{j, 1.0}});
  return makeFeature(s, {{i, 1.0 - t}, {j, t}});
}

Feature closestOfEdges(const Simplex& s, int i, int j, int k) {
  Feature best = closestOnSegment(s, i, j);
  for (const Feature& f : {closestOnSegment(s, j, k), closestOnSegment(s, k, i)}) {
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return best;
}

// Voronoi-region walk of the triangle (after Ericson, Real-Time Collision
// Detection 5.1.5) with the query point at the origin.
Feature closestOnTriangle(const Simplex& s, int i, int j, int k, double flatTolerance) {
  const Vec3& a = s.vertices[i].w;
  const Vec3& b = s.vertices[j].w;
  const Vec3& c = s.vertices[k].w;
  const Vec3 ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= flatTolerance * ab.squaredNorm() * ac.squaredNorm()) return closestOfEdges(s, i, j, k);
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0.0 && d2 <= 0.0) return makeFeature(s, {{i, 1.0}});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0.0 && d4 <= d3) return makeFeature(s, {{j, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return makeFeature(s, {{i, 1.0 - t}, {j, t}});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0.0 && d5 <= d6) return makeFeature(s, {{k, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return makeFeature(s, {{i, 1.0 - t}, {k, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return makeFeature(s, {{j, 1.0 - t}, {k, t}});
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return makeFeature(s, {{i, 1.0 - v - w}, {j, v}, {k, w}});
}

// Returns true with the origin inside; otherwise the closest face feature.
bool closestOnTetrahedron(const Simplex& s, double flatTolerance, Feature& best) {
  const Vec3& a = s.vertices[0].w;
  const Vec3 ab = s.vertices[1].w - a, ac = s.vertices[2].w - a, ad = s.vertices[3].w - a;
  const double volume = ab.dot(ac.cross(ad));
  const double scale = ab.norm() * ac.norm() * ad.norm();
  const bool flat = volume * volume <= flatTolerance * scale * scale;
  constexpr std::array<std::array<int, 4>, 4> faces{{{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}}};
  bool outsideAny = false;
  best.distanceSquared = std::numeric_limits<double>::infinity();
  for (const auto& [i, j, k, opposite] : faces) {
    const Vec3& p = s.vertices[i].w;
    const Vec3 normal = (s.vertices[j].w - p).cross(s.vertices[k].w - p);
    const bool outside = normal.dot(-p) * normal.dot(s.vertices[opposite].w - p) < 0.0;
    if (!outside && !flat) continue;
    outsideAny = true;
    const Feature f = closestOnTriangle(s, i, j, k, flatTolerance);
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return !outsideAny;
}

void applyFeature(const Simplex& simplex, const Feature& feature, Simplex& reduced) {
  reduced.size = feature.count;
  for (int n = 0; n < feature.count; ++n) {
    reduced.vertices[n] = simplex.vertices[feature.index[n]];
    reduced.weights[n] = feature.weight[n];
  }
}

}  // namespace

Vec3 Simplex::closestPoint() const {
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < size; ++i) sum += weights[i] * vertices[i].w;
  return sum;
}

Vec3 Simplex::pointA() const {
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < size; ++i) sum += weights[i] * vertices[i].a;
  return sum;
}

Vec3 Simplex::pointB() const {
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < size; ++i) sum += weights[i] * vertices[i].b;
  return sum;
}

bool reduceToClosest(Simplex& simplex, Simplex& reduced, double flatTolerance) {
  Feature feature;
  switch (simplex.size) {
    case 1: feature = makeFeature(simplex, {{0, 1.0}}); break;
    case 2: feature = closestOnSegment(simplex, 0, 1); break;
    case 3: feature = closestOnTriangle(simplex, 0, 1, 2, flatTolerance); break;
    default:
      if (closestOnTetrahedron(simplex, flatTolerance, feature)) {
        simplex.weights.fill(0.25);  // origin inside: weights are not used
        return true;
      }
  }
  applyFeature(simplex, feature, reduced);
  return false;
}

}  // namespace physdbg
