#include "engine/contacts/manifold_builder.h"

#include <algorithm>
#include <cmath>

namespace physdbg {
namespace {

// The reference face must face the contact normal to within about 18 degrees;
// otherwise (edge against edge, a vertex into a face at an angle) the single
// narrow-phase point is the contact.
constexpr double minimumFaceAlignment = 0.95;
// Metres; far below any visible offset, far above double round-off at 1e5 m.
constexpr double clipTolerance = 1e-6;

std::uint32_t mixTags(std::uint32_t a, std::uint32_t b, std::uint32_t plane) {
  return (0x800u | ((a * 31u + b) * 7u + plane)) & 0xFFFu;
}

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

// Sutherland-Hodgman against one side plane; segments and points clip too.
// Points within `tolerance` outside the plane count as inside: a box resting
// squarely on another has its corners exactly on the side planes, and without
// the tolerance round-off would turn them into intersection points one step
// and back the next, changing their feature ids and losing warm starting.
void clipAgainstPlane(const std::vector<ManifoldScratch::TaggedPoint>& input, const Vec3& planeNormal,
                      double planeOffset, double tolerance, std::uint32_t planeIndex,
                      std::vector<ManifoldScratch::TaggedPoint>& output) {
  output.clear();
  planeOffset += tolerance * planeNormal.norm();
  const std::size_t count = input.size();
  if (count == 1) {
    if (input[0].point.dot(planeNormal) <= planeOffset) output.push_back(input[0]);
    return;
  }
  const std::size_t edges = count == 2 ? 1 : count;
  for (std::size_t i = 0; i < edges; ++i) {
    const auto& current = input[i];
    const auto& next = input[(i + 1) % count];
    const double distanceCurrent = current.point.dot(planeNormal) - planeOffset;
    const double distanceNext = next.point.dot(planeNormal) - planeOffset;
    if (distanceCurrent <= 0.0) output.push_back(current);
    if ((distanceCurrent < 0.0) != (distanceNext < 0.0) && distanceCurrent != distanceNext) {
      const double t = distanceCurrent / (distanceCurrent - distanceNext);
      output.push_back({current.point + t * (next.point - current.point), mixTags(current.tag, next.tag, planeIndex)});
    }
    if (count == 2 && distanceNext <= 0.0) output.push_back(next);
  }
}

// Keeps the deepest point, the one farthest from it, then the points that
// add the most area: four points spanning the contact resist any tipping.
void reduceToFour(ContactManifold& manifold, std::vector<ManifoldPoint>& points) {
  const Vec3& normal = manifold.normal;
  std::size_t chosen[4] = {0, 0, 0, 0};
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].separation < points[chosen[0]].separation) chosen[0] = i;
  const auto position = [&](std::size_t i) { return points[i].pointB; };
  double best = -1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (position(i) - position(chosen[0])).squaredNorm();
    if (d > best) best = d, chosen[1] = i;
  }
  const auto signedArea = [&](std::size_t p, std::size_t q, std::size_t r) {
    return (position(q) - position(p)).cross(position(r) - position(p)).dot(normal);
  };
  best = -1;
  chosen[2] = chosen[0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double area = std::abs(signedArea(chosen[0], chosen[1], i));
    if (area > best) best = area, chosen[2] = i;
  }
  if (signedArea(chosen[0], chosen[1], chosen[2]) < 0) std::swap(chosen[1], chosen[2]);
  best = 0;
  chosen[3] = chosen[0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double added = std::max({-signedArea(chosen[0], chosen[1], i), -signedArea(chosen[1], chosen[2], i),
                                   -signedArea(chosen[2], chosen[0], i)});
    if (added > best) best = added, chosen[3] = i;
  }
  manifold.pointCount = 0;
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && std::find(chosen, chosen + k, chosen[k]) != chosen + k) continue;
    manifold.points[manifold.pointCount++] = points[chosen[k]];
  }
}

}  // namespace

void buildManifold(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                   const ContactResult& result, double speculativeDistance, ManifoldScratch& scratch,
                   ContactManifold& manifold) {
  const Vec3& normal = result.normal;
  if (a.kind() == ColliderKind::Sphere || b.kind() == ColliderKind::Sphere) {
    singlePoint(ta, tb, result, manifold);
    return;
  }
  findSupportingFeature(a, ta, normal, scratch.featureA);
  findSupportingFeature(b, tb, -normal, scratch.featureB);
  const double alignmentA = scratch.featureA.isFace() ? scratch.featureA.normal.dot(normal) : -1.0;
  const double alignmentB = scratch.featureB.isFace() ? -scratch.featureB.normal.dot(normal) : -1.0;
  // Prefer A's face unless B's is clearly better aligned, so the choice does
  // not flicker between steps when both are equally good.
  const bool referenceIsA = alignmentA >= alignmentB - 1e-3;
  const double alignment = referenceIsA ? alignmentA : alignmentB;
  if (alignment < minimumFaceAlignment) {
    singlePoint(ta, tb, result, manifold);
    return;
  }
  const SupportingFeature& reference = referenceIsA ? scratch.featureA : scratch.featureB;
  const SupportingFeature& incident = referenceIsA ? scratch.featureB : scratch.featureA;
  const Vec3& faceNormal = reference.normal;

  scratch.polygon.clear();
  for (std::size_t i = 0; i < incident.points.size(); ++i)
    scratch.polygon.push_back({incident.points[i], static_cast<std::uint32_t>(i + 1)});
  const std::size_t sides = reference.points.size();
  for (std::size_t i = 0; i < sides && !scratch.polygon.empty(); ++i) {
    const Vec3& start = reference.points[i];
    const Vec3 sideNormal = (reference.points[(i + 1) % sides] - start).cross(faceNormal);
    clipAgainstPlane(scratch.polygon, sideNormal, sideNormal.dot(start), clipTolerance, static_cast<std::uint32_t>(i),
                     scratch.clipped);
    std::swap(scratch.polygon, scratch.clipped);
  }

  manifold.normal = referenceIsA ? faceNormal : Vec3(-faceNormal);
  const double faceOffset = faceNormal.dot(reference.points[0]);
  const std::uint32_t featureBase = (referenceIsA ? 0u : 1u << 31) | (std::uint32_t(reference.index & 0x3FF) << 21) |
                                    (std::uint32_t(incident.index & 0x1FF) << 12);
  std::vector<ManifoldPoint>& kept = scratch.kept;
  kept.clear();
  ContactManifold candidate = manifold;
  for (const auto& tagged : scratch.polygon) {
    const double separation = tagged.point.dot(faceNormal) - faceOffset;
    if (separation > speculativeDistance) continue;
    const Vec3 onReference = tagged.point - separation * faceNormal;
    candidate.pointCount = 0;
    if (referenceIsA) addPoint(candidate, ta, tb, onReference, tagged.point, featureBase | tagged.tag);
    else addPoint(candidate, ta, tb, tagged.point, onReference, featureBase | tagged.tag);
    kept.push_back(candidate.points[0]);
  }
  if (kept.empty()) {
    singlePoint(ta, tb, result, manifold);
    return;
  }
  if (kept.size() <= static_cast<std::size_t>(ContactManifold::maxPoints)) {
    manifold.pointCount = 0;
    for (const ManifoldPoint& point : kept) manifold.points[manifold.pointCount++] = point;
    return;
  }
  reduceToFour(manifold, kept);
}

}  // namespace physdbg
