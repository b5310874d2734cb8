#include "gpu/narrow_phase_shader.h"

namespace physdbg::gpu {

// A port of the CPU narrow phase and box-box manifold to float:
// analytic_contacts.cpp, box_box_contact.cpp, box_face.cpp,
// box_box_manifold.cpp and manifold_points.cpp (reduceToFour). The
// tolerances that were set for double round-off are widened to float's; each
// says which CPU constant it stands for.
const char* narrowPhaseShaderSource() {
  return R"GLSL(#version 430
layout(local_size_x = 64) in;

const uint kSphere = 0u, kBox = 1u, kCapsule = 2u;
const uint kFlagBoxBox = 1u, kFlagNeedsCpu = 2u;

// box_box_contact.cpp kParallelSine (1e-8 for double): float's direction
// error eps / sine balances the axis left out (sine * size) near 1e-3-1e-4;
// a nearly parallel edge pair that is not the best axis cannot win anyway.
const float kParallelSine = 1e-3;
// kTieTolerance (1e-10 of the pair's size for double): a face of A beats a
// face of B, a face an edge, within it; float round-off is about 1e-7
const float kTieTolerance = 1e-6;
// kWitnessTolerance (1e-10 of the pair's size for double); too strict a
// value only sends more separated pairs to the CPU, which is exact
const float kWitnessTolerance = 1e-6;
// NarrowPhaseOptions::touchingTolerance, metres
const float kTouchingTolerance = 1e-6;
// manifold_points.h
const float kMinimumFaceAlignment = 0.95;
const float kReferenceFaceHysteresis = 1e-3;
const float kClipTolerance = 1e-6;
// float round-off added to kClipTolerance, relative to the reference face's size
const float kClipRoundOff = 4e-7;
// box_box_manifold.cpp kReductionTieMargin (1e-9 for double)
const float kReductionTieMargin = 1e-5;
// a sphere centre this close (relative) to a capsule's core: the CPU's EPA decides
const float kDegenerateCore = 1e-5;

struct Pose { vec4 high; vec4 low; vec4 rotation; };  // rotation: unit quaternion xyzw
struct Shape { vec4 parameters; };  // box: half extents; sphere: radius; capsule: radius, half height; w: kind
struct Request { uvec4 bodies; };   // a, b, reach (float bits), unused
struct Result {
  vec4 normal;          // xyz: A to B, world; w: signed distance
  vec4 pointA;          // relative to A's position
  vec4 pointB;
  vec4 manifoldNormal;  // w: point count
  uvec4 flags;
  vec4 manifoldA[4];    // w: separation
  vec4 manifoldB[4];
  uvec4 featureIds;
};

layout(std430, binding = 0) readonly buffer Poses { Pose poses[]; };
layout(std430, binding = 1) readonly buffer Shapes { Shape shapes[]; };
layout(std430, binding = 2) readonly buffer Requests { Request requests[]; };
layout(std430, binding = 3) writeonly buffer Results { Result results[]; };
layout(location = 0) uniform uint requestCount;

mat3 rotationMatrix(vec4 q) {
  float x = q.x, y = q.y, z = q.z, w = q.w;
  return mat3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + z * w), 2.0 * (x * z - y * w),
              2.0 * (x * y - z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + x * w),
              2.0 * (x * z + y * w), 2.0 * (y * z - x * w), 1.0 - 2.0 * (x * x + y * y));
}

float signOf(float value) { return value < 0.0 ? -1.0 : 1.0; }

struct Contact { vec3 normal; float signedDistance; vec3 pointA; vec3 pointB; bool needsCpu; };

Contact swapped(Contact contact) {
  Contact reversed = contact;
  reversed.normal = -contact.normal;
  reversed.pointA = contact.pointB;
  reversed.pointB = contact.pointA;
  return reversed;
}

// ---- spheres and capsules (positions relative to A's position, world axes)

Contact collideSpheres(float radiusA, float radiusB, vec3 centreB) {
  float distance = length(centreB);
  vec3 normal = distance > 0.0 ? centreB / distance : vec3(0.0, 1.0, 0.0);
  return Contact(normal, distance - radiusA - radiusB, radiusA * normal, centreB - radiusB * normal, false);
}

Contact collideBoxSphere(vec3 extents, mat3 rotation, vec3 boxCentre, float radius, vec3 sphereCentre) {
  vec3 local = transpose(rotation) * (sphereCentre - boxCentre);
  vec3 clamped = clamp(local, -extents, extents);
  vec3 outside = local - clamped;
  float gap = length(outside);
  vec3 localNormal;
  vec3 localPoint = clamped;
  float signedDistance;
  if (gap > 0.0) {
    localNormal = outside / gap;
    signedDistance = gap - radius;
  } else {
    vec3 faceDistance = extents - abs(local);
    int axis = 0;
    if (faceDistance.y < faceDistance[axis]) axis = 1;
    if (faceDistance.z < faceDistance[axis]) axis = 2;
    localNormal = vec3(0.0);
    localNormal[axis] = local[axis] < 0.0 ? -1.0 : 1.0;
    localPoint[axis] = localNormal[axis] * extents[axis];
    signedDistance = -faceDistance[axis] - radius;
  }
  vec3 normal = rotation * localNormal;
  return Contact(normal, signedDistance, boxCentre + rotation * localPoint, sphereCentre - radius * normal, false);
}

// Normal from the capsule to the sphere.
Contact collideCapsuleSphere(vec2 capsule, mat3 rotation, vec3 capsuleCentre, float radius, vec3 sphereCentre) {
  vec3 axis = rotation[1];
  float along = clamp(dot(sphereCentre - capsuleCentre, axis), -capsule.y, capsule.y);
  vec3 core = capsuleCentre + along * axis;
  vec3 delta = sphereCentre - core;
  float distance = length(delta);
  bool degenerate = distance <= kDegenerateCore * (capsule.x + capsule.y + radius);
  vec3 normal = degenerate ? vec3(0.0, 1.0, 0.0) : delta / distance;
  return Contact(normal, distance - capsule.x - radius, core + capsule.x * normal, sphereCentre - radius * normal,
                 degenerate);
}

// ---- box faces and clipping (box_face.cpp)

struct BoxFace { int axis; float sign; int index; vec3 corners[4]; };

BoxFace boxFaceAlong(vec3 extents, vec3 direction) {
  vec3 magnitude = abs(direction);
  int axis = 0;
  if (magnitude.y > magnitude[axis]) axis = 1;
  if (magnitude.z > magnitude[axis]) axis = 2;
  BoxFace face;
  face.axis = axis;
  face.sign = direction[axis] < 0.0 ? -1.0 : 1.0;
  face.index = 2 * axis + (face.sign < 0.0 ? 1 : 0);
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const vec2 pattern[4] = vec2[4](vec2(1.0, 1.0), vec2(-1.0, 1.0), vec2(-1.0, -1.0), vec2(1.0, -1.0));
  for (int i = 0; i < 4; ++i) {
    vec3 corner;
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
// on (box_face.h), first in the low byte.
const int kPolygonCapacity = 8;
vec3 clipPoints[2 * kPolygonCapacity];
uint clipLines[2 * kPolygonCapacity];
int clipCount[2];
int clipCurrent = 0;

void startPolygon() {
  clipCurrent = 0;
  clipCount[0] = 0;
}

void push(int target, vec3 point, uint lines) {
  if (clipCount[target] < kPolygonCapacity) {
    clipPoints[target * kPolygonCapacity + clipCount[target]] = point;
    clipLines[target * kPolygonCapacity + clipCount[target]] = lines;
    ++clipCount[target];
  }
}

uint packLines(uint first, uint second) { return first | (second << 8); }

void pushCorner(vec3 point, int corner) { push(clipCurrent, point, packLines(uint((corner + 3) % 4), uint(corner))); }

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
vec3 polygonPoint(int i) { return clipPoints[clipCurrent * kPolygonCapacity + i]; }
uint polygonLines(int i) { return clipLines[clipCurrent * kPolygonCapacity + i]; }

void clipAgainstPlane(int coordinate, float sign, float limit, uint line) {
  int source = clipCurrent, target = 1 - clipCurrent;
  clipCount[target] = 0;
  int count = clipCount[source];
  int edges = count == 2 ? 1 : (count == 1 ? 0 : count);
  if (count == 1) {
    vec3 point = clipPoints[source * kPolygonCapacity];
    if (sign * point[coordinate] - limit <= 0.0) push(target, point, clipLines[source * kPolygonCapacity]);
  }
  for (int i = 0; i < edges; ++i) {
    int next = (i + 1) % count;
    vec3 current = clipPoints[source * kPolygonCapacity + i], following = clipPoints[source * kPolygonCapacity + next];
    uint currentLines = clipLines[source * kPolygonCapacity + i];
    uint followingLines = clipLines[source * kPolygonCapacity + next];
    float distanceCurrent = sign * current[coordinate] - limit;
    float distanceNext = sign * following[coordinate] - limit;
    if (distanceCurrent <= 0.0) push(target, current, currentLines);
    if ((distanceCurrent < 0.0) != (distanceNext < 0.0) && distanceCurrent != distanceNext) {
      float t = distanceCurrent / (distanceCurrent - distanceNext);
      push(target, current + t * (following - current), packLines(sharedLine(currentLines, followingLines), line));
    }
    if (count == 2 && distanceNext <= 0.0) push(target, following, followingLines);
  }
  clipCurrent = target;
}

void clipToFaceSides(BoxFace face, float tolerance) {
  vec3 extents = abs(face.corners[0]);
  int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  ivec4 coordinates = ivec4(v, u, v, u);
  vec4 signs = vec4(face.sign, -1.0, -face.sign, 1.0);
  for (int side = 0; side < 4 && polygonCount() > 0; ++side)
    clipAgainstPlane(coordinates[side], signs[side], extents[coordinates[side]] + tolerance, uint(4 + side));
}

// ---- box against box by separating axes (box_box_contact.cpp), in A's frame

struct PairFrame { vec3 halfA; vec3 halfB; mat3 rotation; mat3 absRotation; vec3 offset; float size; };

const int kFaceA = 0, kFaceB = 1, kEdge = 2;
struct Axis { int kind; int indexA; int indexB; float separation; vec3 normal; };

void consider(inout Axis best, Axis candidate, float margin) {
  if (candidate.separation > best.separation + margin) best = candidate;
}

Axis noAxis() { return Axis(kFaceA, 0, 0, -3.0e38, vec3(1.0, 0.0, 0.0)); }

vec3 rowOf(mat3 matrix, int i) { return vec3(matrix[0][i], matrix[1][i], matrix[2][i]); }

Axis faceAxisOfA(PairFrame pair, int i) {
  vec3 normal = vec3(0.0);
  normal[i] = signOf(pair.offset[i]);
  float separation = abs(pair.offset[i]) - pair.halfA[i] - dot(rowOf(pair.absRotation, i), pair.halfB);
  return Axis(kFaceA, i, 0, separation, normal);
}

Axis faceAxisOfB(PairFrame pair, int j) {
  float centreDistance = dot(pair.rotation[j], pair.offset);
  float separation = abs(centreDistance) - dot(pair.absRotation[j], pair.halfA) - pair.halfB[j];
  return Axis(kFaceB, 0, j, separation, signOf(centreDistance) * pair.rotation[j]);
}

bool edgeAxis(PairFrame pair, int i, int j, out Axis axis) {
  vec3 unit = vec3(0.0);
  unit[i] = 1.0;
  vec3 crossed = cross(unit, pair.rotation[j]);
  float crossLength = length(crossed);
  axis = noAxis();
  if (crossLength < kParallelSine) return false;
  vec3 direction = crossed / crossLength;
  float centreDistance = dot(direction, pair.offset);
  float radiusA = dot(abs(direction), pair.halfA);
  float radiusB = dot(abs(transpose(pair.rotation) * direction), pair.halfB);
  axis = Axis(kEdge, i, j, abs(centreDistance) - radiusA - radiusB, signOf(centreDistance) * direction);
  return true;
}

Axis bestAxis(PairFrame pair) {
  float margin = kTieTolerance * pair.size;
  Axis best = noAxis();
  for (int i = 0; i < 3; ++i) consider(best, faceAxisOfA(pair, i), 0.0);
  Axis bestOfB = noAxis();
  for (int j = 0; j < 3; ++j) consider(bestOfB, faceAxisOfB(pair, j), 0.0);
  consider(best, bestOfB, margin);
  Axis bestEdge = noAxis();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Axis edge;
      if (edgeAxis(pair, i, j, edge)) consider(bestEdge, edge, 0.0);
    }
  consider(best, bestEdge, margin);
  return best;
}

struct Witness { vec3 pointA; vec3 pointB; bool exact; };

vec3 supportCorner(vec3 extents, vec3 direction) {
  return vec3(signOf(direction.x) * extents.x, signOf(direction.y) * extents.y, signOf(direction.z) * extents.z);
}

struct FacePoints { vec3 onReference; vec3 onIncident; float separation; bool found; };

FacePoints deepestClippedPoint(vec3 referenceHalf, vec3 referenceDirection, vec3 incidentHalf, mat3 incidentRotation,
                               vec3 incidentOffset) {
  BoxFace referenceFace = boxFaceAlong(referenceHalf, referenceDirection);
  int axis = referenceFace.axis, u = (axis + 1) % 3, v = (axis + 2) % 3;
  vec3 incidentDirection = -(transpose(incidentRotation) * referenceDirection);
  FacePoints deepest = FacePoints(vec3(0.0), vec3(0.0), 3.0e38, false);
  vec3 corner = incidentRotation * supportCorner(incidentHalf, incidentDirection) + incidentOffset;
  if (abs(corner[u]) <= referenceHalf[u] && abs(corner[v]) <= referenceHalf[v]) {
    deepest.separation = referenceFace.sign * corner[axis] - referenceHalf[axis];
    deepest.onIncident = corner;
    deepest.found = true;
  } else {
    BoxFace incidentFace = boxFaceAlong(incidentHalf, incidentDirection);
    startPolygon();
    for (int i = 0; i < 4; ++i) pushCorner(incidentRotation * incidentFace.corners[i] + incidentOffset, i);
    clipToFaceSides(referenceFace, 0.0);
    for (int k = 0; k < polygonCount(); ++k) {
      float separation = referenceFace.sign * polygonPoint(k)[axis] - referenceHalf[axis];
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

Witness faceWitness(PairFrame pair, Axis axis, float tolerance) {
  Witness witness = Witness(vec3(0.0), vec3(0.0), false);
  FacePoints face;
  if (axis.kind == kFaceA) {
    face = deepestClippedPoint(pair.halfA, axis.normal, pair.halfB, pair.rotation, pair.offset);
    witness.pointA = face.onReference;
    witness.pointB = face.onIncident;
  } else {
    mat3 inverse = transpose(pair.rotation);
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

void closestPointsOfSegments(vec3 p0, vec3 d1, vec3 q0, vec3 d2, out vec3 p, out vec3 q) {
  vec3 r = p0 - q0;
  float a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2), c = dot(d1, r), f = dot(d2, r);
  float denominator = a * e - b * b;
  float s = denominator > 0.0 ? clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  float t = e > 0.0 ? (b * s + f) / e : 0.0;
  if (t < 0.0) {
    t = 0.0;
    s = a > 0.0 ? clamp(-c / a, 0.0, 1.0) : 0.0;
  } else if (t > 1.0) {
    t = 1.0;
    s = a > 0.0 ? clamp((b - c) / a, 0.0, 1.0) : 0.0;
  }
  p = p0 + s * d1;
  q = q0 + t * d2;
}

Witness edgeWitness(PairFrame pair, Axis axis, float tolerance) {
  vec3 cornerA = supportCorner(pair.halfA, axis.normal);
  cornerA[axis.indexA] = -pair.halfA[axis.indexA];
  vec3 cornerB = supportCorner(pair.halfB, -(transpose(pair.rotation) * axis.normal));
  cornerB[axis.indexB] = -pair.halfB[axis.indexB];
  vec3 edgeA = vec3(0.0);
  edgeA[axis.indexA] = 2.0 * pair.halfA[axis.indexA];
  Witness witness;
  closestPointsOfSegments(cornerA, edgeA, pair.rotation * cornerB + pair.offset,
                          2.0 * pair.halfB[axis.indexB] * pair.rotation[axis.indexB], witness.pointA, witness.pointB);
  vec3 gap = witness.pointB - witness.pointA;
  witness.exact = length(gap - dot(gap, axis.normal) * axis.normal) <= tolerance;
  return witness;
}

// Everything in A's frame; the caller turns it to world axes.
Contact collideBoxes(PairFrame pair) {
  Axis axis = bestAxis(pair);
  float tolerance = kWitnessTolerance * pair.size;
  Witness witness = axis.kind == kEdge ? edgeWitness(pair, axis, tolerance) : faceWitness(pair, axis, tolerance);
  bool needsCpu = axis.separation >= -kTouchingTolerance && !witness.exact;
  return Contact(axis.normal, axis.separation, witness.pointA, witness.pointB, needsCpu);
}

// ---- the box-box manifold (box_box_manifold.cpp), points relative to A's position

struct Manifold { vec3 normal; int count; vec4 pointA[4]; vec3 pointB[4]; uint featureIds[4]; };
// The invocation's manifold, written in place rather than returned (see the polygon).
Manifold manifold;

void singlePoint(Contact contact) {
  manifold.normal = contact.normal;
  manifold.count = 1;
  manifold.pointA[0] = vec4(contact.pointA, dot(contact.pointB - contact.pointA, contact.normal));
  manifold.pointB[0] = contact.pointB;
  manifold.featureIds[0] = 0u;
}

uint featureBase(bool referenceIsA, int referenceIndex, int incidentIndex) {
  return (referenceIsA ? 0u : (1u << 31)) | (uint(referenceIndex & 0x3FF) << 21) | (uint(incidentIndex & 0x1FF) << 12);
}

struct Candidate { vec3 pointA; vec3 pointB; float separation; uint featureId; };
// Per invocation, like the polygon: copies of arrays are what llvmpipe compiles slowly.
Candidate candidates[kPolygonCapacity];

float signedArea(Candidate p, Candidate q, Candidate r, vec3 normal) {
  return dot(cross(q.pointB - p.pointB, r.pointB - p.pointB), normal);
}

// manifold_points.cpp reduceToFour over up to 16 candidates.
void reduceToFour(int count) {
  float spread = 0.0;
  for (int i = 1; i < count; ++i) spread = max(spread, length(candidates[i].pointB - candidates[0].pointB));
  float lengthMargin = kReductionTieMargin * spread, areaMargin = kReductionTieMargin * spread * spread;
  int chosen[4] = int[4](0, 0, 0, 0);
  for (int i = 1; i < count; ++i)
    if (candidates[i].separation < candidates[chosen[0]].separation - lengthMargin) chosen[0] = i;
  float best = -1.0;
  for (int i = 0; i < count; ++i) {
    vec3 delta = candidates[i].pointB - candidates[chosen[0]].pointB;
    float distance = dot(delta, delta);
    if (distance > best + areaMargin) { best = distance; chosen[1] = i; }
  }
  best = -1.0;
  chosen[2] = chosen[0];
  for (int i = 0; i < count; ++i) {
    float triangle = abs(signedArea(candidates[chosen[0]], candidates[chosen[1]], candidates[i], manifold.normal));
    if (triangle > best + areaMargin) { best = triangle; chosen[2] = i; }
  }
  if (signedArea(candidates[chosen[0]], candidates[chosen[1]], candidates[chosen[2]], manifold.normal) < 0.0) {
    int swap = chosen[1];
    chosen[1] = chosen[2];
    chosen[2] = swap;
  }
  best = 0.0;
  chosen[3] = chosen[0];
  for (int i = 0; i < count; ++i) {
    Candidate p0 = candidates[chosen[0]], p1 = candidates[chosen[1]], p2 = candidates[chosen[2]];
    float added = max(max(-signedArea(p0, p1, candidates[i], manifold.normal),
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
    manifold.pointA[manifold.count] = vec4(point.pointA, point.separation);
    manifold.pointB[manifold.count] = point.pointB;
    manifold.featureIds[manifold.count] = point.featureId;
    ++manifold.count;
  }
}

// `contact` in world axes relative to A's position; rotations world from body.
void boxBoxManifold(vec3 halfA, mat3 rotationA, vec3 halfB, mat3 rotationB, vec3 offset, Contact contact,
                        float reach) {
  vec3 directionA = transpose(rotationA) * contact.normal;
  vec3 directionB = -(transpose(rotationB) * contact.normal);
  BoxFace faceA = boxFaceAlong(halfA, directionA);
  BoxFace faceB = boxFaceAlong(halfB, directionB);
  float alignmentA = faceA.sign * directionA[faceA.axis] / length(directionA);
  float alignmentB = faceB.sign * directionB[faceB.axis] / length(directionB);
  bool referenceIsA = alignmentA >= alignmentB - kReferenceFaceHysteresis;
  if ((referenceIsA ? alignmentA : alignmentB) < kMinimumFaceAlignment) {
    singlePoint(contact);
    return;
  }
  vec3 referenceHalf = referenceIsA ? halfA : halfB;
  mat3 referenceRotation = referenceIsA ? rotationA : rotationB;
  vec3 referencePosition = referenceIsA ? vec3(0.0) : offset;
  mat3 incidentRotation = referenceIsA ? rotationB : rotationA;
  vec3 incidentPosition = referenceIsA ? offset : vec3(0.0);
  BoxFace referenceFace = referenceIsA ? faceA : faceB;
  BoxFace incidentFace = referenceIsA ? faceB : faceA;
  mat3 relativeRotation = transpose(referenceRotation) * incidentRotation;
  vec3 relativeOffset = transpose(referenceRotation) * (incidentPosition - referencePosition);
  startPolygon();
  for (int i = 0; i < 4; ++i) pushCorner(relativeRotation * incidentFace.corners[i] + relativeOffset, i);
  float largestHalf = max(referenceHalf.x, max(referenceHalf.y, referenceHalf.z));
  clipToFaceSides(referenceFace, kClipTolerance + kClipRoundOff * largestHalf);

  vec3 faceNormal = referenceFace.sign * referenceRotation[referenceFace.axis];
  manifold.normal = referenceIsA ? faceNormal : -faceNormal;
  float faceOffset = referenceHalf[referenceFace.axis];
  uint base = featureBase(referenceIsA, referenceFace.index, incidentFace.index);
  int kept = 0;
  for (int i = 0; i < polygonCount(); ++i) {
    vec3 onIncident = polygonPoint(i);
    float separation = referenceFace.sign * onIncident[referenceFace.axis] - faceOffset;
    if (separation > reach) continue;
    vec3 onReference = onIncident;
    onReference[referenceFace.axis] = referenceFace.sign * faceOffset;
    vec3 worldIncident = referencePosition + referenceRotation * onIncident;
    vec3 worldReference = referencePosition + referenceRotation * onReference;
    candidates[kept] = Candidate(referenceIsA ? worldReference : worldIncident,
                                 referenceIsA ? worldIncident : worldReference, separation,
                                 base | clipTag(polygonLines(i)));
    ++kept;
  }
  if (kept == 0) {
    singlePoint(contact);
    return;
  }
  if (kept <= 4) {
    manifold.count = kept;
    for (int i = 0; i < kept; ++i) {
      manifold.pointA[i] = vec4(candidates[i].pointA, candidates[i].separation);
      manifold.pointB[i] = candidates[i].pointB;
      manifold.featureIds[i] = candidates[i].featureId;
    }
    return;
  }
  reduceToFour(kept);
}

// ---- one request

Contact toWorld(Contact contact, mat3 rotationA) {
  return Contact(rotationA * contact.normal, contact.signedDistance, rotationA * contact.pointA,
                 rotationA * contact.pointB, contact.needsCpu);
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= requestCount) return;
  uvec4 request = requests[index].bodies;
  Pose poseA = poses[request.x], poseB = poses[request.y];
  vec4 shapeA = shapes[request.x].parameters, shapeB = shapes[request.y].parameters;
  float reach = uintBitsToFloat(request.z);
  // Both positions lie near each other: the high parts subtract exactly.
  vec3 offset = (poseB.high.xyz - poseA.high.xyz) + (poseB.low.xyz - poseA.low.xyz);
  mat3 rotationA = rotationMatrix(poseA.rotation), rotationB = rotationMatrix(poseB.rotation);
  uint kindA = uint(shapeA.w), kindB = uint(shapeB.w);
  Contact contact;
  uint flags = 0u;
  if (kindA == kBox && kindB == kBox) {
    PairFrame pair;
    pair.halfA = shapeA.xyz;
    pair.halfB = shapeB.xyz;
    pair.rotation = transpose(rotationA) * rotationB;
    pair.absRotation = mat3(abs(pair.rotation[0]), abs(pair.rotation[1]), abs(pair.rotation[2]));
    pair.offset = transpose(rotationA) * offset;
    pair.size = length(pair.halfA) + length(pair.halfB);
    contact = toWorld(collideBoxes(pair), rotationA);
    boxBoxManifold(shapeA.xyz, rotationA, shapeB.xyz, rotationB, offset, contact, reach);
    flags |= kFlagBoxBox;
  } else {
    if (kindA == kSphere && kindB == kSphere) contact = collideSpheres(shapeA.x, shapeB.x, offset);
    else if (kindA == kBox) contact = collideBoxSphere(shapeA.xyz, rotationA, vec3(0.0), shapeB.x, offset);
    else if (kindB == kBox) contact = swapped(collideBoxSphere(shapeB.xyz, rotationB, offset, shapeA.x, vec3(0.0)));
    else if (kindA == kCapsule) contact = collideCapsuleSphere(shapeA.xy, rotationA, vec3(0.0), shapeB.x, offset);
    else contact = swapped(collideCapsuleSphere(shapeB.xy, rotationB, offset, shapeA.x, vec3(0.0)));
    singlePoint(contact);
  }
  if (contact.needsCpu) flags |= kFlagNeedsCpu;
  Result result;
  result.normal = vec4(contact.normal, contact.signedDistance);
  result.pointA = vec4(contact.pointA, 0.0);
  result.pointB = vec4(contact.pointB, 0.0);
  result.manifoldNormal = vec4(manifold.normal, float(manifold.count));
  result.flags = uvec4(flags, 0u, 0u, 0u);
  for (int i = 0; i < 4; ++i) {
    bool used = i < manifold.count;
    result.manifoldA[i] = used ? manifold.pointA[i] : vec4(0.0);
    result.manifoldB[i] = used ? vec4(manifold.pointB[i], 0.0) : vec4(0.0);
    result.featureIds[i] = used ? manifold.featureIds[i] : 0u;
  }
  results[index] = result;
}
)GLSL";
}

}  // namespace physdbg::gpu
