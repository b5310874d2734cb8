#include "engine/contacts/manifold_points.h"

#include <algorithm>
#include <cmath>

namespace physdbg {

void addPoint(ContactManifold& manifold, const Transform& ta, const Transform& tb, const Vec3& pointA,
              const Vec3& pointB, std::uint32_t featureId) {
  ManifoldPoint& point = manifold.points[manifold.pointCount++];
  point = ManifoldPoint{};
  point.pointA = pointA;
  point.pointB = pointB;
  point.localA = ta.applyInverse(pointA);
  point.localB = tb.applyInverse(pointB);
  point.separation = (pointB - pointA).dot(manifold.normal);
  point.featureId = featureId;
}

void singlePoint(const Transform& ta, const Transform& tb, const ContactResult& result, ContactManifold& manifold) {
  manifold.normal = result.normal;
  manifold.pointCount = 0;
  addPoint(manifold, ta, tb, result.pointA, result.pointB, 0);
}

void reduceToFour(ContactManifold& manifold, std::span<const ManifoldPoint> points, double tieMargin) {
  const Vec3& normal = manifold.normal;
  const auto position = [&](std::size_t i) { return points[i].pointB; };
  // Margins in metres (separations) and square metres (squared distances,
  // areas), from the points' spread.
  double spread = 0;
  for (std::size_t i = 1; i < points.size(); ++i) spread = std::max(spread, (position(i) - position(0)).norm());
  const double length = tieMargin * spread, area = tieMargin * spread * spread;
  std::size_t chosen[4] = {0, 0, 0, 0};
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].separation < points[chosen[0]].separation - length) chosen[0] = i;
  double best = -1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (position(i) - position(chosen[0])).squaredNorm();
    if (d > best + area) best = d, chosen[1] = i;
  }
  const auto signedArea = [&](std::size_t p, std::size_t q, std::size_t r) {
    return (position(q) - position(p)).cross(position(r) - position(p)).dot(normal);
  };
  best = -1;
  chosen[2] = chosen[0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double triangle = std::abs(signedArea(chosen[0], chosen[1], i));
    if (triangle > best + area) best = triangle, chosen[2] = i;
  }
  if (signedArea(chosen[0], chosen[1], chosen[2]) < 0) std::swap(chosen[1], chosen[2]);
  best = 0;
  chosen[3] = chosen[0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double added = std::max({-signedArea(chosen[0], chosen[1], i), -signedArea(chosen[1], chosen[2], i),
                                   -signedArea(chosen[2], chosen[0], i)});
    if (added > best + area) best = added, chosen[3] = i;
  }
  manifold.pointCount = 0;
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && std::find(chosen, chosen + k, chosen[k]) != chosen + k) continue;
    manifold.points[manifold.pointCount++] = points[chosen[k]];
  }
}

}  // namespace physdbg
