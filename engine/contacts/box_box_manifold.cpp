#include "engine/contacts/box_box_manifold.h"

#include <array>

#include "engine/contacts/box_face.h"
#include "engine/contacts/feature_ids.h"
#include "engine/contacts/manifold_points.h"
#include "engine/narrowphase/narrow_phase_tolerances.h"

namespace physdbg {
namespace {

constexpr double kReductionTieMargin = tolerances::reductionTieMargin;  // narrow_phase_tolerances.h

// One box of the pair as the clipping sees it.
struct PlacedBox {
  const Vec3& halfExtents;
  const Transform& transform;
  Mat3 rotation;
};

// The incident face's corners in the reference box's frame.
ClipPolygon incidentPolygon(const BoxFace& incidentFace, const Mat3& relativeRotation, const Vec3& relativeOffset) {
  ClipPolygon polygon;
  for (int i = 0; i < 4; ++i) polygon.pushCorner(relativeRotation * incidentFace.corners[i] + relativeOffset, i);
  return polygon;
}

}  // namespace

void buildBoxBoxManifold(const BoxCollider& a, const Transform& ta, const BoxCollider& b, const Transform& tb,
                         const ContactResult& result, double speculativeDistance, ContactManifold& manifold) {
  const PlacedBox boxA{a.halfExtents(), ta, ta.rotation.toRotationMatrix()};
  const PlacedBox boxB{b.halfExtents(), tb, tb.rotation.toRotationMatrix()};
  const Vec3 directionA = boxA.rotation.transpose() * result.normal;
  const Vec3 directionB = -(boxB.rotation.transpose() * result.normal);
  const BoxFace faceA = boxFaceAlong(boxA.halfExtents, directionA);
  const BoxFace faceB = boxFaceAlong(boxB.halfExtents, directionB);
  const double alignmentA = faceA.sign * directionA[faceA.axis] / directionA.norm();
  const double alignmentB = faceB.sign * directionB[faceB.axis] / directionB.norm();
  const bool referenceIsA = alignmentA >= alignmentB - referenceFaceHysteresis;
  if ((referenceIsA ? alignmentA : alignmentB) < minimumFaceAlignment) {
    singlePoint(ta, tb, result, manifold);
    return;
  }
  const PlacedBox& reference = referenceIsA ? boxA : boxB;
  const PlacedBox& incident = referenceIsA ? boxB : boxA;
  const BoxFace& referenceFace = referenceIsA ? faceA : faceB;
  const BoxFace& incidentFace = referenceIsA ? faceB : faceA;
  // Incident box in the reference box's frame.
  const Mat3 relativeRotation = reference.rotation.transpose() * incident.rotation;
  const Vec3 relativeOffset =
      reference.rotation.transpose() * (incident.transform.position - reference.transform.position);
  ClipPolygon polygon = incidentPolygon(incidentFace, relativeRotation, relativeOffset);
  clipToFaceSides(referenceFace, clipTolerance, polygon);

  const Vec3 faceNormal = referenceFace.sign * reference.rotation.col(referenceFace.axis);
  manifold.normal = referenceIsA ? faceNormal : Vec3(-faceNormal);
  const double faceOffset = reference.halfExtents[referenceFace.axis];
  const std::uint32_t base = featureBase(referenceIsA, referenceFace.index, incidentFace.index);
  // Points within reach, as indices into the clipped polygon; ManifoldPoints
  // are made only for the ones kept (usually all, four or fewer).
  std::array<int, 16> kept;
  std::size_t keptCount = 0;
  for (int i = 0; i < polygon.count; ++i)
    if (referenceFace.sign * polygon.points[i].point[referenceFace.axis] - faceOffset <= speculativeDistance)
      kept[keptCount++] = i;
  const auto makePoint = [&](int index, ManifoldPoint& point) {
    const Vec3& onIncident = polygon.points[index].point;
    Vec3 onReference = onIncident;
    onReference[referenceFace.axis] = referenceFace.sign * faceOffset;
    const Vec3 worldIncident = reference.transform.position + reference.rotation * onIncident;
    const Vec3 worldReference = reference.transform.position + reference.rotation * onReference;
    const Vec3 incidentLocal = relativeRotation.transpose() * (onIncident - relativeOffset);
    point = ManifoldPoint{};
    point.pointA = referenceIsA ? worldReference : worldIncident;
    point.pointB = referenceIsA ? worldIncident : worldReference;
    point.localA = referenceIsA ? onReference : incidentLocal;
    point.localB = referenceIsA ? incidentLocal : onReference;
    point.separation = referenceFace.sign * onIncident[referenceFace.axis] - faceOffset;
    point.featureId = base | clipTag(polygon.points[index]);
  };
  if (keptCount == 0) {
    singlePoint(ta, tb, result, manifold);
    return;
  }
  if (keptCount <= static_cast<std::size_t>(ContactManifold::maxPoints)) {
    manifold.pointCount = static_cast<int>(keptCount);
    for (std::size_t i = 0; i < keptCount; ++i) makePoint(kept[i], manifold.points[i]);
    return;
  }
  std::array<ManifoldPoint, 16> candidates;
  for (std::size_t i = 0; i < keptCount; ++i) makePoint(kept[i], candidates[i]);
  reduceToFour(manifold, std::span<const ManifoldPoint>(candidates.data(), keptCount), kReductionTieMargin);
}

}  // namespace physdbg
