#pragma once
// The `grid` layer: a ground grid under the scene with a metre scale and an
// axis gizmo, so a picture tells how big things are and which way is up.
// Built from bounds alone (no engine), so any producer or viewer can add it.
#include <string>

#include "debugdraw/primitives.h"

namespace physdbg::debugdraw {

// Where the grid goes. Lines lie at whole multiples of `spacing` on the plane
// perpendicular to the world axis nearest `up`, at the bounds' bottom (their
// minimum along that axis, or maximum when `up` points down it).
struct GroundGridPlan {
  int upAxis = 1;                 // 0, 1, 2: x, y, z
  int planeAxes[2] = {0, 2};      // the other two, ascending
  double spacing = 1;             // metres, 1, 2 or 5 x 10^k
  Vec3 corner = Vec3::Zero();     // the grid's lowest corner on the plane
  int cells[2] = {0, 0};          // along planeAxes[0] and planeAxes[1]
};

// At most this many cells across the larger side.
inline constexpr int maxGroundGridCells = 20;

// The smallest 1-2-5 x 10^k spacing giving at most 16 cells across `span`
// metres: with a spacing of margin on each side and snapping to multiples,
// that is at most maxGroundGridCells. Throws std::invalid_argument unless
// `span` is finite and positive.
double groundGridSpacing(double span);

// Covers the bounds' footprint with a margin of at least one spacing. A
// footprint under a millimetre across (a point, an empty scene's zero bounds)
// gets a 1 m one around its centre. Throws std::invalid_argument for
// non-finite bounds or `up`, bounds with a minimum above their maximum, a zero
// `up`, or bounds too large for a finite span.
GroundGridPlan planGroundGrid(const Vec3& boundsMin, const Vec3& boundsMax, const Vec3& up);

// A distance along the grid in units that read at its spacing: km from 100 m,
// m from 10 cm, cm from 1 cm, mm below ("0.5 km", "1 m", "25 cm", "5 mm").
std::string groundGridDistance(double metres, double spacing);

// Appends the grid to `frame`, every primitive tagged tagOf(Layer::Grid):
// faint grey lines, every fifth (counted from the corner) and the border
// brighter; labels with the distance from the corner at those brighter lines,
// along the longer side's edge away from the corner; at the corner, x (red),
// y (green) and z (blue) arrows one spacing long, labelled "x", "y", "z".
// Same checks as planGroundGrid.
void emitGroundGrid(const Vec3& boundsMin, const Vec3& boundsMax, const Vec3& up, Frame& frame);

}  // namespace physdbg::debugdraw
