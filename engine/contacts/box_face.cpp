#include "engine/contacts/box_face.h"

#include <algorithm>

namespace physdbg {
namespace {

// The line the polygon edge from `from` to `to` lies on: the one they share.
std::uint8_t sharedLine(const ClipPolygon::Point& from, const ClipPolygon::Point& to) {
  for (std::uint8_t line : from.lines)
    if (line == to.lines[0] || line == to.lines[1]) return line;
  return from.lines[1];  // only for a polygon round-off has bent; any stable choice will do
}

// Side plane i of a face runs along its edge from corner i to corner i + 1;
// in the box's frame it is sign * x[coordinate] <= limit.
struct SidePlane {
  int coordinate;
  double sign;
};

SidePlane sidePlane(const BoxFace& face, int side) {
  const int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  switch (side) {
    case 0: return {v, face.sign};   // corners (+u, +v) to (-u, +v), v scaled by the face's sign
    case 1: return {u, -1.0};        // (-u, +v) to (-u, -v)
    case 2: return {v, -face.sign};  // (-u, -v) to (+u, -v)
    default: return {u, 1.0};        // (+u, -v) to (+u, +v)
  }
}

// One Sutherland-Hodgman pass against side plane `line` (4 + side index).
void clipAgainstPlane(const ClipPolygon& input, const SidePlane& plane, double limit, std::uint8_t line,
                      ClipPolygon& output) {
  output.count = 0;
  const int count = input.count;
  const auto distance = [&](const Vec3& point) { return plane.sign * point[plane.coordinate] - limit; };
  if (count == 1) {
    if (distance(input.points[0].point) <= 0.0) output.push(input.points[0].point, input.points[0].lines);
    return;
  }
  const int edges = count == 2 ? 1 : count;
  for (int i = 0; i < edges; ++i) {
    const ClipPolygon::Point& current = input.points[i];
    const ClipPolygon::Point& next = input.points[(i + 1) % count];
    const double distanceCurrent = distance(current.point);
    const double distanceNext = distance(next.point);
    if (distanceCurrent <= 0.0) output.push(current.point, current.lines);
    if ((distanceCurrent < 0.0) != (distanceNext < 0.0) && distanceCurrent != distanceNext) {
      const double t = distanceCurrent / (distanceCurrent - distanceNext);
      output.push(current.point + t * (next.point - current.point), {sharedLine(current, next), line});
    }
    if (count == 2 && distanceNext <= 0.0) output.push(next.point, next.lines);
  }
}

}  // namespace

BoxFace boxFaceAlong(const Vec3& halfExtents, const Vec3& localDirection) {
  BoxFace face;
  localDirection.cwiseAbs().maxCoeff(&face.axis);
  face.sign = localDirection[face.axis] < 0.0 ? -1.0 : 1.0;
  face.index = 2 * face.axis + (face.sign < 0 ? 1 : 0);
  const int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  constexpr double pattern[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (int i = 0; i < 4; ++i) {
    Vec3& corner = face.corners[i];
    corner[face.axis] = face.sign * halfExtents[face.axis];
    corner[u] = pattern[i][0] * halfExtents[u];
    corner[v] = pattern[i][1] * halfExtents[v] * face.sign;
  }
  return face;
}

std::uint32_t clipTag(const ClipPolygon::Point& point) {
  const int first = std::min(point.lines[0], point.lines[1]), second = std::max(point.lines[0], point.lines[1]);
  if (second < 4) return static_cast<std::uint32_t>(second - first == 1 ? second : first) + 1u;  // corner
  return 0x800u | static_cast<std::uint32_t>(first * 8 + second);
}

// Ping-pongs between `polygon` and one scratch polygon; four passes end in
// `polygon` itself, so only an early exit (nothing left) copies.
void clipToFaceSides(const BoxFace& face, double tolerance, ClipPolygon& polygon) {
  const Vec3 half = face.corners[0].cwiseAbs();
  ClipPolygon scratch;
  ClipPolygon* input = &polygon;
  ClipPolygon* output = &scratch;
  for (int side = 0; side < 4 && input->count > 0; ++side) {
    const SidePlane plane = sidePlane(face, side);
    clipAgainstPlane(*input, plane, half[plane.coordinate] + tolerance, static_cast<std::uint8_t>(4 + side), *output);
    std::swap(input, output);
  }
  if (input != &polygon) {
    polygon.count = input->count;
    std::copy_n(input->points.begin(), input->count, polygon.points.begin());
  }
}

}  // namespace physdbg
