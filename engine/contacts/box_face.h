#pragma once
// A box's face as a fixed-size polygon in the box's own frame, and the
// clipping of another box's face against its side planes. This is the
// allocation-free core that both the box-box narrow phase (for its witness
// points) and the box-box manifold builder use; the general builder does the
// same with supporting features in world space for any pair of shapes.
#include <array>
#include <cstdint>

#include "engine/math.h"

namespace physdbg {

struct BoxFace {
  int axis = 0;       // local axis the face is normal to
  double sign = 1.0;  // +1 or -1: which of the two faces
  int index = 0;      // 2 * axis + (sign < 0), the id findSupportingFeature gives it
  // Box-local corners, counter-clockwise seen from outside, in the order
  // findSupportingFeature lists them (the order the feature ids depend on).
  std::array<Vec3, 4> corners;
  Vec3 normal() const {
    Vec3 n = Vec3::Zero();
    n[axis] = sign;
    return n;
  }
};

// The face whose outward normal is closest to `localDirection` (box frame;
// need not be unit). Ties go to the lower axis, a zero component to the
// positive face, as in findSupportingFeature.
BoxFace boxFaceAlong(const Vec3& halfExtents, const Vec3& localDirection);

// A polygon being clipped. Each point knows the two lines it lies on: an
// incident-face edge (0-3, edge k runs from corner k to corner k + 1) or a
// reference side plane (4-7). A corner lies on its two edges, a point made by
// clipping on the line its polygon edge lay on and the clipping plane. That
// pair names the point geometrically, so its feature tag is the same every
// step the same edge crosses the same side, whatever else was clipped: no
// hash of the clipping history, which can collide (two points of one
// manifold with one id would share a warm-start impulse).
// 16 points: a quad clipped by four planes has at most 8, the rest is room
// for round-off making a nearly edge-on quad cross a plane more often than
// twice (extra points are then dropped, never written out of bounds).
struct ClipPolygon {
  struct Point {
    Vec3 point;
    std::array<std::uint8_t, 2> lines;
  };
  std::array<Point, 16> points;
  int count = 0;
  void push(const Vec3& point, std::array<std::uint8_t, 2> lines) {
    if (count < static_cast<int>(points.size())) points[count++] = {point, lines};
  }
  // Corners of a quad (the incident face), tagged as the corners they are.
  void pushCorner(const Vec3& point, int corner) {
    push(point, {static_cast<std::uint8_t>((corner + 3) % 4), static_cast<std::uint8_t>(corner)});
  }
};

// Feature tag of a clipped point: 1-4 for the incident face's corners (as
// the general builder tags them), otherwise bit 11 and the pair of lines.
std::uint32_t clipTag(const ClipPolygon::Point& point);

// Clips `polygon` (coordinates in the reference box's frame) to the four side
// planes of `face`, in the order of its corners. Points within `tolerance`
// outside a side plane count as inside (see manifold_points.h for why
// resting contacts need that); a polygon reduced to two points is clipped as
// a segment, one as a point, as the general builder does.
void clipToFaceSides(const BoxFace& face, double tolerance, ClipPolygon& polygon);

}  // namespace physdbg
