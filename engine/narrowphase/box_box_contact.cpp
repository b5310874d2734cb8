#include "engine/narrowphase/box_box_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/contacts/box_face.h"
#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/narrow_phase_tolerances.h"

namespace physdbg {
namespace {

// narrow_phase_tolerances.h says why each is what it is.
constexpr double kParallelSine = tolerances::parallelSine;
constexpr double kTieTolerance = tolerances::tieTolerance;
constexpr double kWitnessTolerance = tolerances::witnessTolerance;

// B as seen from A's frame, and what every axis test needs.
struct PairFrame {
  Vec3 halfA, halfB;
  Mat3 rotation;     // columns: B's axes in A's frame
  Mat3 absRotation;  // |rotation|, the projection radii's weights
  Vec3 offset;       // B's centre in A's frame
  double size;       // |halfA| + |halfB|, the scale of relative tolerances
};

enum class AxisKind { FaceA, FaceB, Edge };

struct Axis {
  AxisKind kind = AxisKind::FaceA;
  int indexA = 0, indexB = 0;  // A's and B's axis (face axes use one of them)
  double separation = -std::numeric_limits<double>::infinity();
  Vec3 normal = Vec3::UnitX();  // A's frame, unit, from A towards B
};

double signOf(double value) { return value < 0.0 ? -1.0 : 1.0; }

void consider(Axis& best, const Axis& candidate, double margin) {
  if (candidate.separation > best.separation + margin) best = candidate;
}

Axis faceAxisOfA(const PairFrame& pair, int i) {
  Axis axis{AxisKind::FaceA, i, 0, 0.0, Vec3::Zero()};
  axis.separation = std::abs(pair.offset[i]) - pair.halfA[i] - pair.absRotation.row(i).dot(pair.halfB);
  axis.normal[i] = signOf(pair.offset[i]);
  return axis;
}

Axis faceAxisOfB(const PairFrame& pair, int j) {
  const double centreDistance = pair.rotation.col(j).dot(pair.offset);
  Axis axis{AxisKind::FaceB, 0, j, 0.0, signOf(centreDistance) * pair.rotation.col(j)};
  axis.separation = std::abs(centreDistance) - pair.absRotation.col(j).dot(pair.halfA) - pair.halfB[j];
  return axis;
}

// Returns false when the edges are too close to parallel to give an axis.
bool edgeAxis(const PairFrame& pair, int i, int j, Axis& axis) {
  const Vec3 cross = Vec3::Unit(i).cross(pair.rotation.col(j));
  const double length = cross.norm();
  if (length < kParallelSine) return false;
  const Vec3 direction = cross / length;
  const double centreDistance = direction.dot(pair.offset);
  const double radiusA = direction.cwiseAbs().dot(pair.halfA);
  const double radiusB = (pair.rotation.transpose() * direction).cwiseAbs().dot(pair.halfB);
  axis = Axis{AxisKind::Edge, i, j, std::abs(centreDistance) - radiusA - radiusB, signOf(centreDistance) * direction};
  return true;
}

// The axis of largest separation (smallest overlap), ties to faces of A,
// then faces of B, then edges.
Axis bestAxis(const PairFrame& pair) {
  const double margin = kTieTolerance * pair.size;
  Axis best;
  for (int i = 0; i < 3; ++i) consider(best, faceAxisOfA(pair, i), 0.0);
  Axis bestOfB;
  for (int j = 0; j < 3; ++j) consider(bestOfB, faceAxisOfB(pair, j), 0.0);
  consider(best, bestOfB, margin);
  Axis bestEdge;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Axis edge;
      if (edgeAxis(pair, i, j, edge)) consider(bestEdge, edge, 0.0);
    }
  }
  consider(best, bestEdge, margin);
  return best;
}

// Witness points in A's frame, and whether their gap proves the separation.
struct Witness {
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
  bool exact = false;
};

// Corner of a box farthest along `direction` (box frame; zero components
// take the positive side, as BoxCollider::localSupport does).
Vec3 supportCorner(const Vec3& half, const Vec3& direction) {
  return {signOf(direction.x()) * half.x(), signOf(direction.y()) * half.y(), signOf(direction.z()) * half.z()};
}

// Face contact in the reference box's frame: the incident box's deepest
// point over the reference face's rectangle (no tolerance: the points must
// really lie over the face). Usually its deepest corner is over the face;
// otherwise its most opposed face is clipped to the rectangle. `found` is
// false when nothing of the incident face lies over the reference face.
struct FacePoints {
  Vec3 onReference = Vec3::Zero(), onIncident = Vec3::Zero();
  double separation = std::numeric_limits<double>::infinity();
  bool found = false;
};

FacePoints deepestClippedPoint(const Vec3& referenceHalf, const Vec3& referenceDirection, const Vec3& incidentHalf,
                               const Mat3& incidentRotation, const Vec3& incidentOffset) {
  const BoxFace referenceFace = boxFaceAlong(referenceHalf, referenceDirection);
  const int axis = referenceFace.axis, u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Vec3 incidentDirection = -(incidentRotation.transpose() * referenceDirection);
  FacePoints deepest;
  const Vec3 corner = incidentRotation * supportCorner(incidentHalf, incidentDirection) + incidentOffset;
  if (std::abs(corner[u]) <= referenceHalf[u] && std::abs(corner[v]) <= referenceHalf[v]) {
    deepest.separation = referenceFace.sign * corner[axis] - referenceHalf[axis];
    deepest.onIncident = corner;
    deepest.found = true;
  } else {
    const BoxFace incidentFace = boxFaceAlong(incidentHalf, incidentDirection);
    ClipPolygon polygon;
    for (int i = 0; i < 4; ++i) polygon.pushCorner(incidentRotation * incidentFace.corners[i] + incidentOffset, i);
    clipToFaceSides(referenceFace, 0.0, polygon);
    for (int k = 0; k < polygon.count; ++k) {
      const Vec3& point = polygon.points[k].point;
      const double separation = referenceFace.sign * point[axis] - referenceHalf[axis];
      if (separation >= deepest.separation) continue;
      deepest.separation = separation;
      deepest.onIncident = point;
      deepest.found = true;
    }
  }
  deepest.onReference = deepest.onIncident;
  deepest.onReference[axis] = referenceFace.sign * referenceHalf[axis];
  return deepest;
}

Witness faceWitness(const PairFrame& pair, const Axis& axis, double tolerance) {
  Witness witness;
  FacePoints face;
  if (axis.kind == AxisKind::FaceA) {
    face = deepestClippedPoint(pair.halfA, axis.normal, pair.halfB, pair.rotation, pair.offset);
    witness.pointA = face.onReference;
    witness.pointB = face.onIncident;
  } else {  // B's face, worked in B's frame and brought back
    const Mat3 inverse = pair.rotation.transpose();
    face = deepestClippedPoint(pair.halfB, -(inverse * axis.normal), pair.halfA, inverse, -(inverse * pair.offset));
    witness.pointA = pair.rotation * face.onIncident + pair.offset;
    witness.pointB = pair.rotation * face.onReference + pair.offset;
  }
  witness.exact = face.found && face.separation <= axis.separation + tolerance;
  if (!face.found) {  // the incident box's deepest corner, moved out along the normal
    witness.pointB = pair.rotation * supportCorner(pair.halfB, -(pair.rotation.transpose() * axis.normal)) + pair.offset;
    witness.pointA = witness.pointB - axis.separation * axis.normal;
  }
  return witness;
}

// Closest points of the segments p0 + s * d1 and q0 + t * d2, s and t in
// [0, 1]; the segments may not be parallel (the caller's edges are not).
void closestPointsOfSegments(const Vec3& p0, const Vec3& d1, const Vec3& q0, const Vec3& d2, Vec3& p, Vec3& q) {
  const Vec3 r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), b = d1.dot(d2), c = d1.dot(r), f = d2.dot(r);
  const double denominator = a * e - b * b;
  double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = e > 0.0 ? (b * s + f) / e : 0.0;
  if (t < 0.0) {
    t = 0.0;
    s = a > 0.0 ? std::clamp(-c / a, 0.0, 1.0) : 0.0;
  } else if (t > 1.0) {
    t = 1.0;
    s = a > 0.0 ? std::clamp((b - c) / a, 0.0, 1.0) : 0.0;
  }
  p = p0 + s * d1;
  q = q0 + t * d2;
}

// Edge pair: A's edge along axis indexA that is farthest along the normal,
// B's edge along indexB farthest against it. Their closest points are the
// witness; both edges lie in their boxes' supporting planes, so the gap
// along the normal is the separation and the witness is exact when the gap
// has no sideways part (the closest points are inside both edges).
Witness edgeWitness(const PairFrame& pair, const Axis& axis, double tolerance) {
  Vec3 cornerA = supportCorner(pair.halfA, axis.normal);
  cornerA[axis.indexA] = -pair.halfA[axis.indexA];
  const Vec3 directionB = -(pair.rotation.transpose() * axis.normal);
  Vec3 cornerB = supportCorner(pair.halfB, directionB);
  cornerB[axis.indexB] = -pair.halfB[axis.indexB];
  Witness witness;
  closestPointsOfSegments(cornerA, 2.0 * pair.halfA[axis.indexA] * Vec3::Unit(axis.indexA),
                          pair.rotation * cornerB + pair.offset,
                          2.0 * pair.halfB[axis.indexB] * pair.rotation.col(axis.indexB), witness.pointA,
                          witness.pointB);
  const Vec3 gap = witness.pointB - witness.pointA;
  witness.exact = (gap - gap.dot(axis.normal) * axis.normal).norm() <= tolerance;
  return witness;
}

}  // namespace

std::optional<ContactResult> collideBoxes(const BoxCollider& a, const Transform& ta, const BoxCollider& b,
                                          const Transform& tb, double touchingTolerance) {
  const Mat3 rotationA = ta.rotation.toRotationMatrix();
  PairFrame pair;
  pair.halfA = a.halfExtents();
  pair.halfB = b.halfExtents();
  pair.rotation = rotationA.transpose() * tb.rotation.toRotationMatrix();
  pair.absRotation = pair.rotation.cwiseAbs();
  pair.offset = rotationA.transpose() * (tb.position - ta.position);
  pair.size = pair.halfA.norm() + pair.halfB.norm();

  const Axis axis = bestAxis(pair);
  const double tolerance = kWitnessTolerance * pair.size;
  const Witness witness =
      axis.kind == AxisKind::Edge ? edgeWitness(pair, axis, tolerance) : faceWitness(pair, axis, tolerance);
  if (axis.separation >= -touchingTolerance && !witness.exact) return std::nullopt;
  ContactResult result = classifyContact(axis.separation, rotationA * axis.normal, ta.position + rotationA * witness.pointA,
                                         ta.position + rotationA * witness.pointB, touchingTolerance);
  result.usedBoxBox = true;
  return result;
}

}  // namespace physdbg
