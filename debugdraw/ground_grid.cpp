#include "debugdraw/ground_grid.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace physdbg::debugdraw {
namespace {

// Cells across the footprint itself; margins and snapping add up to four.
constexpr double kFootprintCells = 16;
// Below this a footprint is a point: it gets kPointFootprint around it.
constexpr double kSmallestFootprint = 1e-3;
constexpr double kPointFootprint = 1;
// A spacing this small a fraction of the coordinates would put neighbouring
// lines within a few ulps of each other far from the origin.
constexpr double kSmallestRelativeSpan = 1e-12;
constexpr int kMajorEvery = 5;

constexpr Color kMinorLine{0.5f, 0.52f, 0.56f, 0.35f};
constexpr Color kMajorLine{0.72f, 0.74f, 0.78f, 0.8f};
constexpr Color kScaleText{0.8f, 0.82f, 0.86f, 1.0f};
constexpr Color kAxisColors[3] = {{1.0f, 0.3f, 0.3f, 1.0f}, {0.35f, 0.9f, 0.35f, 1.0f}, {0.4f, 0.55f, 1.0f, 1.0f}};
constexpr const char* kAxisNames[3] = {"x", "y", "z"};
constexpr float kScaleTextSize = 1;
constexpr float kAxisTextSize = 2;

void requireValid(const Vec3& boundsMin, const Vec3& boundsMax, const Vec3& up) {
  if (!boundsMin.allFinite() || !boundsMax.allFinite())
    throw std::invalid_argument("ground grid: bounds are not finite");
  if ((boundsMin.array() > boundsMax.array()).any())
    throw std::invalid_argument("ground grid: bounds have a minimum above their maximum");
  if (!up.allFinite() || up.isZero(0)) throw std::invalid_argument("ground grid: up must be finite and non-zero");
}

int nearestAxis(const Vec3& direction) {
  int axis = 0;
  direction.cwiseAbs().maxCoeff(&axis);
  return axis;
}

// Snaps [low, high] outwards to multiples of `spacing`, one spacing beyond.
void snapRange(double low, double high, double spacing, double& start, int& cells) {
  const double first = std::floor(low / spacing) - 1, last = std::ceil(high / spacing) + 1;
  start = first * spacing;
  cells = static_cast<int>(last - first);
}

Vec3 onPlane(const GroundGridPlan& plan, double first, double second) {
  Vec3 point = plan.corner;
  point[plan.planeAxes[0]] += first;
  point[plan.planeAxes[1]] += second;
  return point;
}

bool isMajor(int line, int cells) { return line % kMajorEvery == 0 || line == cells; }

// Lines across axis `along`'s direction: one at each multiple of the spacing along it.
void addLines(const GroundGridPlan& plan, int along, Frame& frame) {
  const int across = 1 - along;
  const double length = plan.cells[across] * plan.spacing;
  for (int line = 0; line <= plan.cells[along]; ++line) {
    double from[2], to[2];
    from[along] = to[along] = line * plan.spacing;
    from[across] = 0;
    to[across] = length;
    const Color color = isMajor(line, plan.cells[along]) ? kMajorLine : kMinorLine;
    frame.lines.push_back({onPlane(plan, from[0], from[1]), onPlane(plan, to[0], to[1]), color, tagOf(Layer::Grid)});
  }
}

// Distances from the corner at the major lines of the longer side, on the
// edge away from the gizmo so the two never crowd each other, half a spacing
// outside the grid so they clear its lines.
void addScale(const GroundGridPlan& plan, Frame& frame) {
  const int along = plan.cells[1] > plan.cells[0] ? 1 : 0, across = 1 - along;
  for (int line = 0; line <= plan.cells[along]; line += kMajorEvery) {
    double offset[2];
    offset[along] = line * plan.spacing;
    offset[across] = (plan.cells[across] + 0.5) * plan.spacing;
    frame.labels.push_back({onPlane(plan, offset[0], offset[1]), kScaleTextSize,
                            groundGridDistance(line * plan.spacing, plan.spacing), kScaleText, tagOf(Layer::Grid)});
  }
}

void addGizmo(const GroundGridPlan& plan, Frame& frame) {
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 direction = Vec3::Unit(axis);
    const Vec3 tip = plan.corner + direction * plan.spacing;
    frame.arrows.push_back({plan.corner, tip, kAxisColors[axis], tagOf(Layer::Grid)});
    frame.labels.push_back(
        {tip + direction * (0.15 * plan.spacing), kAxisTextSize, kAxisNames[axis], kAxisColors[axis], tagOf(Layer::Grid)});
  }
}

}  // namespace

double groundGridSpacing(double span) {
  if (!(span > 0) || !std::isfinite(span))
    throw std::invalid_argument("ground grid: span must be finite and positive");
  const double wanted = span / kFootprintCells;
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)) - 1);  // a decade low: log10 may round up
  for (double power = decade;; power *= 10)
    for (double mantissa : {1.0, 2.0, 5.0})
      if (mantissa * power >= wanted) return mantissa * power;
}

GroundGridPlan planGroundGrid(const Vec3& boundsMin, const Vec3& boundsMax, const Vec3& up) {
  requireValid(boundsMin, boundsMax, up);
  GroundGridPlan plan;
  plan.upAxis = nearestAxis(up);
  plan.planeAxes[0] = plan.upAxis == 0 ? 1 : 0;
  plan.planeAxes[1] = plan.upAxis == 2 ? 1 : 2;
  Vec3 low = boundsMin, high = boundsMax;
  const Vec3 extent = high - low;
  double footprint = std::max(extent[plan.planeAxes[0]], extent[plan.planeAxes[1]]);
  if (!std::isfinite(footprint)) throw std::invalid_argument("ground grid: bounds too large");
  if (footprint < kSmallestFootprint) {
    const Vec3 centre = 0.5 * (low + high);
    low = centre - Vec3::Constant(0.5 * kPointFootprint);
    high = centre + Vec3::Constant(0.5 * kPointFootprint);
    footprint = kPointFootprint;
  }
  const double magnitude = std::max(low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff());
  plan.spacing = groundGridSpacing(std::max(footprint, kSmallestRelativeSpan * magnitude));
  for (int side = 0; side < 2; ++side) {
    const int axis = plan.planeAxes[side];
    snapRange(low[axis], high[axis], plan.spacing, plan.corner[axis], plan.cells[side]);
  }
  plan.corner[plan.upAxis] = up[plan.upAxis] > 0 ? boundsMin[plan.upAxis] : boundsMax[plan.upAxis];
  return plan;
}

std::string groundGridDistance(double metres, double spacing) {
  struct Unit {
    double metres, smallestSpacing;
    const char* name;
  };
  // The labels sit every fifth line: at 100 m spacing "0.5 km", "1 km"; at
  // 0.1 m "0.5 m", "1 m"; at 5 cm "25 cm".
  constexpr Unit kUnits[] = {{1000, 100, "km"}, {1, 0.1, "m"}, {0.01, 0.01, "cm"}, {0.001, 0, "mm"}};
  const Unit* unit = std::begin(kUnits);
  while (spacing < unit->smallestSpacing * (1 - 1e-9)) ++unit;  // the last one takes any spacing
  std::ostringstream text;
  text << std::setprecision(12) << metres / unit->metres << ' ' << unit->name;
  return text.str();
}

void emitGroundGrid(const Vec3& boundsMin, const Vec3& boundsMax, const Vec3& up, Frame& frame) {
  const GroundGridPlan plan = planGroundGrid(boundsMin, boundsMax, up);
  addLines(plan, 0, frame);
  addLines(plan, 1, frame);
  addScale(plan, frame);
  addGizmo(plan, frame);
}

}  // namespace physdbg::debugdraw
