#include "engine/contacts/manifold_builder.h"

#include <algorithm>
#include <cmath>

#include "engine/colliders/box_collider.h"
#include "engine/contacts/box_box_manifold.h"
#include "engine/contacts/feature_ids.h"
#include "engine/contacts/manifold_points.h"

namespace physdbg {
namespace {

// Sutherland-Hodgman against one side plane; segments and points clip too.
// Points within `tolerance` outside the plane count as inside (see
// clipTolerance).
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

}  // namespace

void buildManifold(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                   const ContactResult& result, double speculativeDistance, ManifoldScratch& scratch,
                   ContactManifold& manifold) {
  if (result.usedBoxBox && a.kind() == ColliderKind::Box && b.kind() == ColliderKind::Box) {
    buildBoxBoxManifold(static_cast<const BoxCollider&>(a), ta, static_cast<const BoxCollider&>(b), tb, result,
                        speculativeDistance, manifold);
    return;
  }
  buildGeneralManifold(a, ta, b, tb, result, speculativeDistance, scratch, manifold);
}

void buildGeneralManifold(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
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
  const bool referenceIsA = alignmentA >= alignmentB - referenceFaceHysteresis;
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
  const std::uint32_t base = featureBase(referenceIsA, reference.index, incident.index);
  std::vector<ManifoldPoint>& kept = scratch.kept;
  kept.clear();
  ContactManifold candidate = manifold;
  for (const auto& tagged : scratch.polygon) {
    const double separation = tagged.point.dot(faceNormal) - faceOffset;
    if (separation > speculativeDistance) continue;
    const Vec3 onReference = tagged.point - separation * faceNormal;
    candidate.pointCount = 0;
    if (referenceIsA) addPoint(candidate, ta, tb, onReference, tagged.point, base | tagged.tag);
    else addPoint(candidate, ta, tb, tagged.point, onReference, base | tagged.tag);
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
