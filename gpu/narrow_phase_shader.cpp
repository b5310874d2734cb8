#include "gpu/narrow_phase_shader.h"

#include <cstdio>
#include <string>

#include "engine/contacts/manifold_points.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/narrowphase/narrow_phase_tolerances.h"

namespace physdbg::gpu {
namespace {

// A port of the CPU narrow phase and box-box manifold to GLSL doubles:
// analytic_contacts.cpp, box_box_contact.cpp, box_face.cpp,
// box_box_manifold.cpp and manifold_points.cpp (reduceToFour). The
// arithmetic follows the CPU's order where it decides (rotation matrices as
// Eigen builds them, the same comparisons in the same order), so the shader
// takes the CPU's decisions. Every literal carries `lf`: a float literal in a
// double expression would be rounded to float first.
constexpr const char* kBeforeTolerances = R"GLSL(#version 430
layout(local_size_x = 64) in;

const uint kSphere = 0u, kBox = 1u, kCapsule = 2u;
const uint kFlagBoxBox = 1u, kFlagNeedsCpu = 2u, kFlagPointsFromB = 4u;

)GLSL";

constexpr const char* kAfterTolerances = R"GLSL(
struct Pose { dvec4 position; dvec4 rotation; };  // position: w unused; rotation: unit quaternion xyzw
struct Shape { dvec4 parameters; };  // box: half extents; sphere: radius; capsule: radius, half height; w: kind
struct Request { uvec4 bodies; };    // a, b, reach (double: low word, high word)
struct Result {
  dvec4 normal;          // xyz: A to B, world; w: signed distance
  dvec4 pointA;          // relative to A's position
  dvec4 pointB;
  dvec4 manifoldNormal;  // w: point count
  dvec4 manifoldA[4];    // relative to A's position (B's with kFlagPointsFromB); w: separation
  dvec4 manifoldB[4];
  uvec4 flags;
  uvec4 featureIds;
};

layout(std430, binding = 0) readonly buffer Poses { Pose poses[]; };
layout(std430, binding = 1) readonly buffer Shapes { Shape shapes[]; };
layout(std430, binding = 2) readonly buffer Requests { Request requests[]; };
layout(std430, binding = 3) writeonly buffer Results { Result results[]; };
layout(location = 0) uniform uint requestCount;

// As Eigen's Quaternion::toRotationMatrix computes it.
dmat3 rotationMatrix(dvec4 q) {
  double tx = 2.0lf * q.x, ty = 2.0lf * q.y, tz = 2.0lf * q.z;
  double twx = tx * q.w, twy = ty * q.w, twz = tz * q.w;
  double txx = tx * q.x, txy = ty * q.x, txz = tz * q.x;
  double tyy = ty * q.y, tyz = tz * q.y, tzz = tz * q.z;
  return dmat3(1.0lf - (tyy + tzz), txy + twz, txz - twy,
               txy - twz, 1.0lf - (txx + tzz), tyz + twx,
               txz + twy, tyz - twx, 1.0lf - (txx + tyy));
}

// As Eigen's Quaternion * Vector3 computes it (Transform::apply, applyInverse).
dvec3 rotate(dvec4 q, dvec3 v) {
  dvec3 uv = cross(q.xyz, v);
  uv += uv;
  return v + q.w * uv + cross(q.xyz, uv);
}
dvec4 conjugate(dvec4 q) { return dvec4(-q.xyz, q.w); }

double signOf(double value) { return value < 0.0lf ? -1.0lf : 1.0lf; }

struct Contact { dvec3 normal; double signedDistance; dvec3 pointA; dvec3 pointB; bool needsCpu; };

Contact swapped(Contact contact) {
  Contact reversed = contact;
  reversed.normal = -contact.normal;
  reversed.pointA = contact.pointB;
  reversed.pointB = contact.pointA;
  return reversed;
}

// ---- spheres and capsules (positions relative to A's position, world axes)

Contact collideSpheres(double radiusA, double radiusB, dvec3 centreB) {
  double distance = length(centreB);
  dvec3 normal = distance > 0.0lf ? centreB / distance : dvec3(0.0lf, 1.0lf, 0.0lf);
  return Contact(normal, distance - radiusA - radiusB, radiusA * normal, centreB - radiusB * normal, false);
}

// As analytic_contacts.cpp, the box's rotation as its quaternion.
Contact collideBoxSphere(dvec3 extents, dvec4 rotation, dvec3 boxCentre, double radius, dvec3 sphereCentre) {
  dvec3 local = rotate(conjugate(rotation), sphereCentre - boxCentre);
  dvec3 clamped = min(max(local, -extents), extents);
  dvec3 outside = local - clamped;
  double gap = length(outside);
  dvec3 localNormal;
  dvec3 localPoint = clamped;
  double signedDistance;
  if (gap > 0.0lf) {
    localNormal = outside / gap;
    signedDistance = gap - radius;
  } else {
    dvec3 faceDistance = extents - abs(local);
    int axis = 0;  // Eigen's minCoeff: the first of equal smallest
    if (faceDistance.y < faceDistance[axis]) axis = 1;
    if (faceDistance.z < faceDistance[axis]) axis = 2;
    localNormal = dvec3(0.0lf);
    localNormal[axis] = local[axis] < 0.0lf ? -1.0lf : 1.0lf;
    localPoint[axis] = localNormal[axis] * extents[axis];
    signedDistance = -faceDistance[axis] - radius;
  }
  dvec3 normal = rotate(rotation, localNormal);
  return Contact(normal, signedDistance, boxCentre + rotate(rotation, localPoint), sphereCentre - radius * normal,
                 false);
}

// Normal from the capsule to the sphere.
Contact collideCapsuleSphere(dvec2 capsule, dmat3 rotation, dvec3 capsuleCentre, double radius, dvec3 sphereCentre) {
  dvec3 axis = rotation[1];
  double along = clamp(dot(sphereCentre - capsuleCentre, axis), -capsule.y, capsule.y);
  dvec3 core = capsuleCentre + along * axis;
  dvec3 delta = sphereCentre - core;
  double distance = length(delta);
  bool degenerate = distance <= kDegenerateCore * (capsule.x + capsule.y + radius);
  dvec3 normal = degenerate ? dvec3(0.0lf, 1.0lf, 0.0lf) : delta / distance;
  return Contact(normal, distance - capsule.x - radius, core + capsule.x * normal, sphereCentre - radius * normal,
                 degenerate);
}

// ---- box faces and clipping (box_face.cpp)

struct BoxFace { int axis; double sign; int index; dvec3 corners[4]; };

BoxFace boxFaceAlong(dvec3 extents, dvec3 direction) {
  dvec3 magnitude = abs(direction);
  int axis = 0;  // Eigen's maxCoeff: the first of equal largest
  if (magnitude.y > magnitude[axis]) axis = 1;
  if (magnitude.z > magnitude[axis]) axis = 2;
  BoxFace face;
  face.axis = axis;
  face.sign = direction[axis] < 0.0lf ? -1.0lf : 1.0lf;
  face.index = 2 * axis + (face.sign < 0.0lf ? 1 : 0);
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const dvec2 pattern[4] = dvec2[4](dvec2(1.0lf, 1.0lf), dvec2(-1.0lf, 1.0lf), dvec2(-1.0lf, -1.0lf),
                                    dvec2(1.0lf, -1.0lf));
  for (int i = 0; i < 4; ++i) {
    dvec3 corner;
    corner[axis] = face.sign * extents[axis];
    corner[u] = pattern[i].x * extents[u];
    corner[v] = pattern[i].y * extents[v] * face.sign;
    face.corners[i] = corner;
  }
  return face;
}

// The polygon being clipped, ping-ponged between two halves of one
// per-invocation array: passing polygons by value made llvmpipe's compile
// of the shader take many seconds. A point's tag packs the two lines it lies
// on (box_face.h), first in the low byte. 16 points as ClipPolygon holds.
const int kPolygonCapacity = 16;
dvec3 clipPoints[2 * kPolygonCapacity];
uint clipLines[2 * kPolygonCapacity];
int clipCount[2];
int clipCurrent = 0;

void startPolygon() {
  clipCurrent = 0;
  clipCount[0] = 0;
}

void push(int target, dvec3 point, uint lines) {
  if (clipCount[target] < kPolygonCapacity) {
    clipPoints[target * kPolygonCapacity + clipCount[target]] = point;
    clipLines[target * kPolygonCapacity + clipCount[target]] = lines;
    ++clipCount[target];
  }
}

uint packLines(uint first, uint second) { return first | (second << 8); }

void pushCorner(dvec3 point, int corner) { push(clipCurrent, point, packLines(uint((corner + 3) % 4), uint(corner))); }

uint sharedLine(uint from, uint to) {
  uint fromFirst = from & 0xFFu, fromSecond = from >> 8;
  if (fromFirst == (to & 0xFFu) || fromFirst == (to >> 8)) return fromFirst;
  return fromSecond;
}

uint clipTag(uint lines) {
  uint first = min(lines & 0xFFu, lines >> 8), second = max(lines & 0xFFu, lines >> 8);
  if (second < 4u) return (second - first == 1u ? second : first) + 1u;
  return 0x800u | (first * 8u + second);
}

int polygonCount() { return clipCount[clipCurrent]; }
dvec3 polygonPoint(int i) { return clipPoints[clipCurrent * kPolygonCapacity + i]; }
uint polygonLines(int i) { return clipLines[clipCurrent * kPolygonCapacity + i]; }

void clipAgainstPlane(int coordinate, double sign, double limit, uint line) {
  int source = clipCurrent, target = 1 - clipCurrent;
  clipCount[target] = 0;
  int count = clipCount[source];
  int edges = count == 2 ? 1 : (count == 1 ? 0 : count);
  if (count == 1) {
    dvec3 point = clipPoints[source * kPolygonCapacity];
    if (sign * point[coordinate] - limit <= 0.0lf) push(target, point, clipLines[source * kPolygonCapacity]);
  }
  for (int i = 0; i < edges; ++i) {
    int next = (i + 1) % count;
    dvec3 current = clipPoints[source * kPolygonCapacity + i], following = clipPoints[source * kPolygonCapacity + next];
    uint currentLines = clipLines[source * kPolygonCapacity + i];
    uint followingLines = clipLines[source * kPolygonCapacity + next];
    double distanceCurrent = sign * current[coordinate] - limit;
    double distanceNext = sign * following[coordinate] - limit;
    if (distanceCurrent <= 0.0lf) push(target, current, currentLines);
    if ((distanceCurrent < 0.0lf) != (distanceNext < 0.0lf) && distanceCurrent != distanceNext) {
      double t = distanceCurrent / (distanceCurrent - distanceNext);
      push(target, current + t * (following - current), packLines(sharedLine(currentLines, followingLines), line));
    }
    if (count == 2 && distanceNext <= 0.0lf) push(target, following, followingLines);
  }
  clipCurrent = target;
}

void clipToFaceSides(BoxFace face, double tolerance) {
  dvec3 extents = abs(face.corners[0]);
  int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  ivec4 coordinates = ivec4(v, u, v, u);
  dvec4 signs = dvec4(face.sign, -1.0lf, -face.sign, 1.0lf);
  for (int side = 0; side < 4 && polygonCount() > 0; ++side)
    clipAgainstPlane(coordinates[side], signs[side], extents[coordinates[side]] + tolerance, uint(4 + side));
}

// ---- box against box by separating axes (box_box_contact.cpp), in A's frame

struct PairFrame { dvec3 halfA; dvec3 halfB; dmat3 rotation; dmat3 absRotation; dvec3 offset; double size; };

const int kFaceA = 0, kFaceB = 1, kEdge = 2;
struct Axis { int kind; int indexA; int indexB; double separation; dvec3 normal; };

void consider(inout Axis best, Axis candidate, double margin) {
  if (candidate.separation > best.separation + margin) best = candidate;
}

Axis noAxis() { return Axis(kFaceA, 0, 0, -kHuge, dvec3(1.0lf, 0.0lf, 0.0lf)); }

dvec3 rowOf(dmat3 matrix, int i) { return dvec3(matrix[0][i], matrix[1][i], matrix[2][i]); }

Axis faceAxisOfA(PairFrame pair, int i) {
  dvec3 normal = dvec3(0.0lf);
  normal[i] = signOf(pair.offset[i]);
  double separation = abs(pair.offset[i]) - pair.halfA[i] - dot(rowOf(pair.absRotation, i), pair.halfB);
  return Axis(kFaceA, i, 0, separation, normal);
}

Axis faceAxisOfB(PairFrame pair, int j) {
  double centreDistance = dot(pair.rotation[j], pair.offset);
  double separation = abs(centreDistance) - dot(pair.absRotation[j], pair.halfA) - pair.halfB[j];
  return Axis(kFaceB, 0, j, separation, signOf(centreDistance) * pair.rotation[j]);
}

bool edgeAxis(PairFrame pair, int i, int j, out Axis axis) {
  dvec3 unit = dvec3(0.0lf);
  unit[i] = 1.0lf;
  dvec3 crossed = cross(unit, pair.rotation[j]);
  double crossLength = length(crossed);
  axis = noAxis();
  if (crossLength < kParallelSine) return false;
  dvec3 direction = crossed / crossLength;
  double centreDistance = dot(direction, pair.offset);
  double radiusA = dot(abs(direction), pair.halfA);
  double radiusB = dot(abs(transpose(pair.rotation) * direction), pair.halfB);
  axis = Axis(kEdge, i, j, abs(centreDistance) - radiusA - radiusB, signOf(centreDistance) * direction);
  return true;
}

Axis bestAxis(PairFrame pair) {
  double margin = kTieTolerance * pair.size;
  Axis best = noAxis();
  for (int i = 0; i < 3; ++i) consider(best, faceAxisOfA(pair, i), 0.0lf);
  Axis bestOfB = noAxis();
  for (int j = 0; j < 3; ++j) consider(bestOfB, faceAxisOfB(pair, j), 0.0lf);
  consider(best, bestOfB, margin);
  Axis bestEdge = noAxis();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Axis edge;
      if (edgeAxis(pair, i, j, edge)) consider(bestEdge, edge, 0.0lf);
    }
  consider(best, bestEdge, margin);
  return best;
}

struct Witness { dvec3 pointA; dvec3 pointB; bool exact; };

dvec3 supportCorner(dvec3 extents, dvec3 direction) {
  return dvec3(signOf(direction.x) * extents.x, signOf(direction.y) * extents.y, signOf(direction.z) * extents.z);
}

struct FacePoints { dvec3 onReference; dvec3 onIncident; double separation; bool found; };

FacePoints deepestClippedPoint(dvec3 referenceHalf, dvec3 referenceDirection, dvec3 incidentHalf,
                               dmat3 incidentRotation, dvec3 incidentOffset) {
  BoxFace referenceFace = boxFaceAlong(referenceHalf, referenceDirection);
  int axis = referenceFace.axis, u = (axis + 1) % 3, v = (axis + 2) % 3;
  dvec3 incidentDirection = -(transpose(incidentRotation) * referenceDirection);
  FacePoints deepest = FacePoints(dvec3(0.0lf), dvec3(0.0lf), kHuge, false);
  dvec3 corner = incidentRotation * supportCorner(incidentHalf, incidentDirection) + incidentOffset;
  if (abs(corner[u]) <= referenceHalf[u] && abs(corner[v]) <= referenceHalf[v]) {
    deepest.separation = referenceFace.sign * corner[axis] - referenceHalf[axis];
    deepest.onIncident = corner;
    deepest.found = true;
  } else {
    BoxFace incidentFace = boxFaceAlong(incidentHalf, incidentDirection);
    startPolygon();
    for (int i = 0; i < 4; ++i) pushCorner(incidentRotation * incidentFace.corners[i] + incidentOffset, i);
    clipToFaceSides(referenceFace, 0.0lf);
    for (int k = 0; k < polygonCount(); ++k) {
      double separation = referenceFace.sign * polygonPoint(k)[axis] - referenceHalf[axis];
      if (separation >= deepest.separation) continue;
      deepest.separation = separation;
      deepest.onIncident = polygonPoint(k);
      deepest.found = true;
    }
  }
  deepest.onReference = deepest.onIncident;
  deepest.onReference[axis] = referenceFace.sign * referenceHalf[axis];
  return deepest;
}

Witness faceWitness(PairFrame pair, Axis axis, double tolerance) {
  Witness witness = Witness(dvec3(0.0lf), dvec3(0.0lf), false);
  FacePoints face;
  if (axis.kind == kFaceA) {
    face = deepestClippedPoint(pair.halfA, axis.normal, pair.halfB, pair.rotation, pair.offset);
    witness.pointA = face.onReference;
    witness.pointB = face.onIncident;
  } else {
    dmat3 inverse = transpose(pair.rotation);
    face = deepestClippedPoint(pair.halfB, -(inverse * axis.normal), pair.halfA, inverse, -(inverse * pair.offset));
    witness.pointA = pair.rotation * face.onIncident + pair.offset;
    witness.pointB = pair.rotation * face.onReference + pair.offset;
  }
  witness.exact = face.found && face.separation <= axis.separation + tolerance;
  if (!face.found) {
    witness.pointB =
        pair.rotation * supportCorner(pair.halfB, -(transpose(pair.rotation) * axis.normal)) + pair.offset;
    witness.pointA = witness.pointB - axis.separation * axis.normal;
  }
  return witness;
}

void closestPointsOfSegments(dvec3 p0, dvec3 d1, dvec3 q0, dvec3 d2, out dvec3 p, out dvec3 q) {
  dvec3 r = p0 - q0;
  double a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2), c = dot(d1, r), f = dot(d2, r);
  double denominator = a * e - b * b;
  double s = denominator > 0.0lf ? clamp((b * f - c * e) / denominator, 0.0lf, 1.0lf) : 0.0lf;
  double t = e > 0.0lf ? (b * s + f) / e : 0.0lf;
  if (t < 0.0lf) {
    t = 0.0lf;
    s = a > 0.0lf ? clamp(-c / a, 0.0lf, 1.0lf) : 0.0lf;
  } else if (t > 1.0lf) {
    t = 1.0lf;
    s = a > 0.0lf ? clamp((b - c) / a, 0.0lf, 1.0lf) : 0.0lf;
  }
  p = p0 + s * d1;
  q = q0 + t * d2;
}

Witness edgeWitness(PairFrame pair, Axis axis, double tolerance) {
  dvec3 cornerA = supportCorner(pair.halfA, axis.normal);
  cornerA[axis.indexA] = -pair.halfA[axis.indexA];
  dvec3 cornerB = supportCorner(pair.halfB, -(transpose(pair.rotation) * axis.normal));
  cornerB[axis.indexB] = -pair.halfB[axis.indexB];
  dvec3 edgeA = dvec3(0.0lf);
  edgeA[axis.indexA] = 2.0lf * pair.halfA[axis.indexA];
  Witness witness;
  closestPointsOfSegments(cornerA, edgeA, pair.rotation * cornerB + pair.offset,
                          2.0lf * pair.halfB[axis.indexB] * pair.rotation[axis.indexB], witness.pointA,
                          witness.pointB);
  dvec3 gap = witness.pointB - witness.pointA;
  witness.exact = length(gap - dot(gap, axis.normal) * axis.normal) <= tolerance;
  return witness;
}

// Everything in A's frame; the caller turns it to world axes.
Contact collideBoxes(PairFrame pair) {
  Axis axis = bestAxis(pair);
  double tolerance = kWitnessTolerance * pair.size;
  Witness witness = axis.kind == kEdge ? edgeWitness(pair, axis, tolerance) : faceWitness(pair, axis, tolerance);
  bool needsCpu = axis.separation >= -kTouchingTolerance && !witness.exact;
  return Contact(axis.normal, axis.separation, witness.pointA, witness.pointB, needsCpu);
}

// ---- the box-box manifold (box_box_manifold.cpp), points relative to A's
// position, or to B's when B's face is the reference (manifoldFromB)

struct Manifold { dvec3 normal; int count; dvec4 pointA[4]; dvec3 pointB[4]; uint featureIds[4]; };
// The invocation's manifold, written in place rather than returned (see the polygon).
Manifold manifold;
bool manifoldFromB = false;

void singlePoint(Contact contact) {
  manifold.normal = contact.normal;
  manifold.count = 1;
  manifold.pointA[0] = dvec4(contact.pointA, dot(contact.pointB - contact.pointA, contact.normal));
  manifold.pointB[0] = contact.pointB;
  manifold.featureIds[0] = 0u;
  manifoldFromB = false;
}

uint featureBase(bool referenceIsA, int referenceIndex, int incidentIndex) {
  return (referenceIsA ? 0u : (1u << 31)) | (uint(referenceIndex & 0x3FF) << 21) | (uint(incidentIndex & 0x1FF) << 12);
}

struct Candidate { dvec3 pointA; dvec3 pointB; double separation; uint featureId; };
// Per invocation, like the polygon: copies of arrays are what llvmpipe compiles slowly.
Candidate candidates[kPolygonCapacity];

double signedArea(Candidate p, Candidate q, Candidate r, dvec3 normal) {
  return dot(cross(q.pointB - p.pointB, r.pointB - p.pointB), normal);
}

// manifold_points.cpp reduceToFour over up to 16 candidates.
void reduceToFour(int count) {
  double spread = 0.0lf;
  for (int i = 1; i < count; ++i) spread = max(spread, length(candidates[i].pointB - candidates[0].pointB));
  double lengthMargin = kReductionTieMargin * spread, areaMargin = kReductionTieMargin * spread * spread;
  int chosen[4] = int[4](0, 0, 0, 0);
  for (int i = 1; i < count; ++i)
    if (candidates[i].separation < candidates[chosen[0]].separation - lengthMargin) chosen[0] = i;
  double best = -1.0lf;
  for (int i = 0; i < count; ++i) {
    dvec3 delta = candidates[i].pointB - candidates[chosen[0]].pointB;
    double distance = dot(delta, delta);
    if (distance > best + areaMargin) { best = distance; chosen[1] = i; }
  }
  best = -1.0lf;
  chosen[2] = chosen[0];
  for (int i = 0; i < count; ++i) {
    double triangle = abs(signedArea(candidates[chosen[0]], candidates[chosen[1]], candidates[i], manifold.normal));
    if (triangle > best + areaMargin) { best = triangle; chosen[2] = i; }
  }
  if (signedArea(candidates[chosen[0]], candidates[chosen[1]], candidates[chosen[2]], manifold.normal) < 0.0lf) {
    int swap = chosen[1];
    chosen[1] = chosen[2];
    chosen[2] = swap;
  }
  best = 0.0lf;
  chosen[3] = chosen[0];
  for (int i = 0; i < count; ++i) {
    Candidate p0 = candidates[chosen[0]], p1 = candidates[chosen[1]], p2 = candidates[chosen[2]];
    double added = max(max(-signedArea(p0, p1, candidates[i], manifold.normal),
                           -signedArea(p1, p2, candidates[i], manifold.normal)),
                       -signedArea(p2, p0, candidates[i], manifold.normal));
    if (added > best + areaMargin) { best = added; chosen[3] = i; }
  }
  manifold.count = 0;
  for (int k = 0; k < 4; ++k) {
    bool repeated = false;
    for (int m = 0; m < k; ++m) repeated = repeated || chosen[m] == chosen[k];
    if (repeated) continue;
    Candidate point = candidates[chosen[k]];
    manifold.pointA[manifold.count] = dvec4(point.pointA, point.separation);
    manifold.pointB[manifold.count] = point.pointB;
    manifold.featureIds[manifold.count] = point.featureId;
    ++manifold.count;
  }
}

// `contact` in world axes relative to A's position; rotations world from body.
void boxBoxManifold(dvec3 halfA, dmat3 rotationA, dvec3 halfB, dmat3 rotationB, dvec3 offset, Contact contact,
                    double reach) {
  dvec3 directionA = transpose(rotationA) * contact.normal;
  dvec3 directionB = -(transpose(rotationB) * contact.normal);
  BoxFace faceA = boxFaceAlong(halfA, directionA);
  BoxFace faceB = boxFaceAlong(halfB, directionB);
  double alignmentA = faceA.sign * directionA[faceA.axis] / length(directionA);
  double alignmentB = faceB.sign * directionB[faceB.axis] / length(directionB);
  bool referenceIsA = alignmentA >= alignmentB - kReferenceFaceHysteresis;
  if ((referenceIsA ? alignmentA : alignmentB) < kMinimumFaceAlignment) {
    singlePoint(contact);
    return;
  }
  dvec3 referenceHalf = referenceIsA ? halfA : halfB;
  dmat3 referenceRotation = referenceIsA ? rotationA : rotationB;
  dmat3 incidentRotation = referenceIsA ? rotationB : rotationA;
  // The incident box's position relative to the reference box's, as the CPU subtracts them.
  dvec3 incidentPosition = referenceIsA ? offset : -offset;
  BoxFace referenceFace = referenceIsA ? faceA : faceB;
  BoxFace incidentFace = referenceIsA ? faceB : faceA;
  dmat3 relativeRotation = transpose(referenceRotation) * incidentRotation;
  dvec3 relativeOffset = transpose(referenceRotation) * incidentPosition;
  startPolygon();
  for (int i = 0; i < 4; ++i) pushCorner(relativeRotation * incidentFace.corners[i] + relativeOffset, i);
  clipToFaceSides(referenceFace, kClipTolerance);

  dvec3 faceNormal = referenceFace.sign * referenceRotation[referenceFace.axis];
  manifold.normal = referenceIsA ? faceNormal : -faceNormal;
  double faceOffset = referenceHalf[referenceFace.axis];
  uint base = featureBase(referenceIsA, referenceFace.index, incidentFace.index);
  int kept = 0;
  for (int i = 0; i < polygonCount(); ++i) {
    dvec3 onIncident = polygonPoint(i);
    double separation = referenceFace.sign * onIncident[referenceFace.axis] - faceOffset;
    if (separation > reach) continue;
    dvec3 onReference = onIncident;
    onReference[referenceFace.axis] = referenceFace.sign * faceOffset;
    // Relative to the reference box's position; the caller adds it.
    dvec3 worldIncident = referenceRotation * onIncident;
    dvec3 worldReference = referenceRotation * onReference;
    candidates[kept] = Candidate(referenceIsA ? worldReference : worldIncident,
                                 referenceIsA ? worldIncident : worldReference, separation,
                                 base | clipTag(polygonLines(i)));
    ++kept;
  }
  if (kept == 0) {
    singlePoint(contact);
    return;
  }
  manifoldFromB = !referenceIsA;
  if (kept <= 4) {
    manifold.count = kept;
    for (int i = 0; i < kept; ++i) {
      manifold.pointA[i] = dvec4(candidates[i].pointA, candidates[i].separation);
      manifold.pointB[i] = candidates[i].pointB;
      manifold.featureIds[i] = candidates[i].featureId;
    }
    return;
  }
  reduceToFour(kept);
}

// ---- one request

Contact toWorld(Contact contact, dmat3 rotationA) {
  return Contact(rotationA * contact.normal, contact.signedDistance, rotationA * contact.pointA,
                 rotationA * contact.pointB, contact.needsCpu);
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= requestCount) return;
  uvec4 request = requests[index].bodies;
  Pose poseA = poses[request.x], poseB = poses[request.y];
  dvec4 shapeA = shapes[request.x].parameters, shapeB = shapes[request.y].parameters;
  double reach = packDouble2x32(request.zw);
  dvec3 offset = poseB.position.xyz - poseA.position.xyz;
  dmat3 rotationA = rotationMatrix(poseA.rotation), rotationB = rotationMatrix(poseB.rotation);
  uint kindA = uint(shapeA.w), kindB = uint(shapeB.w);
  Contact contact;
  uint flags = 0u;
  if (kindA == kBox && kindB == kBox) {
    PairFrame pair;
    pair.halfA = shapeA.xyz;
    pair.halfB = shapeB.xyz;
    pair.rotation = transpose(rotationA) * rotationB;
    pair.absRotation = dmat3(abs(pair.rotation[0]), abs(pair.rotation[1]), abs(pair.rotation[2]));
    pair.offset = transpose(rotationA) * offset;
    pair.size = length(pair.halfA) + length(pair.halfB);
    contact = toWorld(collideBoxes(pair), rotationA);
    boxBoxManifold(shapeA.xyz, rotationA, shapeB.xyz, rotationB, offset, contact, reach);
    flags |= kFlagBoxBox;
  } else {
    if (kindA == kSphere && kindB == kSphere) contact = collideSpheres(shapeA.x, shapeB.x, offset);
    else if (kindA == kBox) contact = collideBoxSphere(shapeA.xyz, poseA.rotation, dvec3(0.0lf), shapeB.x, offset);
    else if (kindB == kBox) contact = swapped(collideBoxSphere(shapeB.xyz, poseB.rotation, offset, shapeA.x, dvec3(0.0lf)));
    else if (kindA == kCapsule) contact = collideCapsuleSphere(shapeA.xy, rotationA, dvec3(0.0lf), shapeB.x, offset);
    else contact = swapped(collideCapsuleSphere(shapeB.xy, rotationB, offset, shapeA.x, dvec3(0.0lf)));
    singlePoint(contact);
  }
  if (contact.needsCpu) flags |= kFlagNeedsCpu;
  if (manifoldFromB) flags |= kFlagPointsFromB;
  Result result;
  result.normal = dvec4(contact.normal, contact.signedDistance);
  result.pointA = dvec4(contact.pointA, 0.0lf);
  result.pointB = dvec4(contact.pointB, 0.0lf);
  result.manifoldNormal = dvec4(manifold.normal, double(manifold.count));
  result.flags = uvec4(flags, 0u, 0u, 0u);
  for (int i = 0; i < 4; ++i) {
    bool used = i < manifold.count;
    result.manifoldA[i] = used ? manifold.pointA[i] : dvec4(0.0lf);
    result.manifoldB[i] = used ? dvec4(manifold.pointB[i], 0.0lf) : dvec4(0.0lf);
    result.featureIds[i] = used ? manifold.featureIds[i] : 0u;
  }
  results[index] = result;
}
)GLSL";

// A GLSL double literal that reads back as exactly `value`.
std::string glslDouble(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  std::string literal = text;
  if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
  return literal + "lf";
}

std::string constant(const char* name, double value) {
  return std::string("const double ") + name + " = " + glslDouble(value) + ";\n";
}

// Every tolerance is written from the CPU's own constant, not retyped.
std::string tolerances() {
  return "// box_box_contact.cpp (engine/narrowphase/narrow_phase_tolerances.h)\n" +
         constant("kParallelSine", tolerances::parallelSine) + constant("kTieTolerance", tolerances::tieTolerance) +
         constant("kWitnessTolerance", tolerances::witnessTolerance) +
         "// NarrowPhaseOptions::touchingTolerance, metres\n" +
         constant("kTouchingTolerance", NarrowPhaseOptions{}.touchingTolerance) + "// manifold_points.h\n" +
         constant("kMinimumFaceAlignment", minimumFaceAlignment) +
         constant("kReferenceFaceHysteresis", referenceFaceHysteresis) +
         constant("kClipTolerance", clipTolerance) + "// box_box_manifold.cpp\n" +
         constant("kReductionTieMargin", tolerances::reductionTieMargin) +
         "// A sphere centre this close (relative) to a capsule's core: the CPU's EPA\n"
         "// decides the normal (any is as good), so the CPU answers it.\n" +
         constant("kDegenerateCore", 1e-9) + constant("kHuge", 1e300);
}

}  // namespace

const char* narrowPhaseShaderSource() {
  static const std::string source = kBeforeTolerances + tolerances() + kAfterTolerances;
  return source.c_str();
}

}  // namespace physdbg::gpu
