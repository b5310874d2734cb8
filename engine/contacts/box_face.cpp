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

// One Sutherland-Hodgman pass against side plane `side`: normal . x <= offset.
void clipAgainstPlane(const ClipPolygon& input, const Vec3& normal, double offset, std::uint8_t side,
                      ClipPolygon& output) {
  output.count = 0;
  const int count = input.count;
  if (count == 1) {
    if (input.points[0].point.dot(normal) <= offset) output.push(input.points[0].point, input.points[0].lines);
    return;
  }
  const int edges = count == 2 ? 1 : count;
  for (int i = 0; i < edges; ++i) {
    const ClipPolygon::Point& current = input.points[i];
    const ClipPolygon::Point& next = input.points[(i + 1) % count];
    const double distanceCurrent = current.point.dot(normal) - offset;
    const double distanceNext = next.point.dot(normal) - offset;
    if (distanceCurrent <= 0.0) output.push(current.point, current.lines);
    if ((distanceCurrent < 0.0) != (distanceNext < 0.0) && distanceCurrent != distanceNext) {
      const double t = distanceCurrent / (distanceCurrent - distanceNext);
      output.push(current.point + t * (next.point - current.point), {sharedLine(current, next), side});
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

void clipToFaceSides(const BoxFace& face, double tolerance, ClipPolygon& polygon) {
  const Vec3 faceNormal = face.normal();
  ClipPolygon clipped;
  for (int i = 0; i < 4 && polygon.count > 0; ++i) {
    const Vec3& start = face.corners[i];
    const Vec3 sideNormal = (face.corners[(i + 1) % 4] - start).cross(faceNormal);
    const double offset = sideNormal.dot(start) + tolerance * sideNormal.norm();
    clipAgainstPlane(polygon, sideNormal, offset, static_cast<std::uint8_t>(4 + i), clipped);
    polygon = clipped;
  }
}

}  // namespace physdbg
