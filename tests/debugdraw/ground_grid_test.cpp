// The ground grid stays a readable size at any scale (1-2-5 spacing, bounded
// line count), lies at the bottom of the bounds, and is all on the grid layer.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "debugdraw/ground_grid.h"

namespace {

namespace dd = physdbg::debugdraw;
using dd::Vec3;

// True when `spacing` is 1, 2 or 5 times a power of ten.
bool isOneTwoFive(double spacing) {
  const double power = std::pow(10.0, std::floor(std::log10(spacing) + 1e-9));
  const double mantissa = spacing / power;
  for (double allowed : {1.0, 2.0, 5.0})
    if (std::abs(mantissa - allowed) < 1e-9) return true;
  return false;
}

dd::Frame gridFrame(const Vec3& low, const Vec3& high, const Vec3& up) {
  dd::Frame frame;
  dd::emitGroundGrid(low, high, up, frame);
  return frame;
}

TEST(GroundGrid, SpacingIsOneTwoFiveWithAtMostTwentyCells) {
  for (double span : {3.0, 1.0, 7.5, 16.0, 0.004, 123.0, 1e9, 2.5e-3}) {
    const double spacing = dd::groundGridSpacing(span);
    EXPECT_TRUE(isOneTwoFive(spacing)) << span << " -> " << spacing;
    EXPECT_LE(span / spacing, 16.0 + 1e-9) << span;
    EXPECT_GT(span / spacing, 16.0 / 2.5 - 1e-9) << span;  // the next smaller spacing would not do
  }
  EXPECT_DOUBLE_EQ(dd::groundGridSpacing(3.0), 0.2);
  EXPECT_DOUBLE_EQ(dd::groundGridSpacing(16.0), 1.0);
  EXPECT_THROW(dd::groundGridSpacing(0), std::invalid_argument);
  EXPECT_THROW(dd::groundGridSpacing(INFINITY), std::invalid_argument);
}

TEST(GroundGrid, ThreeMetreBoundsGetAFewCellsOfOneTwoFiveSpacing) {
  const dd::GroundGridPlan plan = dd::planGroundGrid({-1.5, 0, -1}, {1.5, 2, 1}, {0, 1, 0});
  EXPECT_TRUE(isOneTwoFive(plan.spacing));
  EXPECT_DOUBLE_EQ(plan.spacing, 0.2);
  EXPECT_LE(plan.cells[0], dd::maxGroundGridCells);
  EXPECT_LE(plan.cells[1], dd::maxGroundGridCells);
  // The footprint plus at least one spacing on every side.
  EXPECT_LE(plan.corner.x(), -1.5 - plan.spacing + 1e-9);
  EXPECT_GE(plan.corner.x() + plan.cells[0] * plan.spacing, 1.5 + plan.spacing - 1e-9);
  EXPECT_LE(plan.corner.z(), -1 - plan.spacing + 1e-9);
  EXPECT_GE(plan.corner.z() + plan.cells[1] * plan.spacing, 1 + plan.spacing - 1e-9);
}

TEST(GroundGrid, HugeBoundsGiveABoundedLineCount) {
  for (double size : {1e9, 1e15, 1e300}) {
    const dd::Frame frame = gridFrame(Vec3(-size, -size, 0), Vec3(size, size, size), {0, 0, 1});
    EXPECT_LE(frame.lines.size(), 2u * (dd::maxGroundGridCells + 1)) << size;
    EXPECT_GE(frame.lines.size(), 8u) << size;
  }
  const dd::GroundGridPlan far = dd::planGroundGrid({1e12, 0, 1e12}, {1e12 + 3, 1, 1e12 + 3}, {0, 1, 0});
  EXPECT_GT(far.corner.x() + far.spacing, far.corner.x());  // lines still apart, far from the origin
  EXPECT_THROW(dd::planGroundGrid(Vec3::Constant(-1.5e308), Vec3::Constant(1.5e308), {0, 1, 0}),
               std::invalid_argument);
}

TEST(GroundGrid, DegenerateBoundsGetAMetreWideGridAroundThem) {
  const dd::GroundGridPlan plan = dd::planGroundGrid(Vec3(4, 2, 7), Vec3(4, 2, 7), {0, 1, 0});
  EXPECT_DOUBLE_EQ(plan.spacing, 0.1);
  for (int side = 0; side < 2; ++side) {
    EXPECT_GE(plan.cells[side], 10);
    EXPECT_LE(plan.cells[side], dd::maxGroundGridCells);
  }
  EXPECT_NEAR(plan.corner.x() + 0.5 * plan.cells[0] * plan.spacing, 4, 1e-9);
  EXPECT_DOUBLE_EQ(plan.corner.y(), 2);
  const dd::Frame frame = gridFrame(Vec3::Zero(), Vec3::Zero(), {0, 1, 0});
  EXPECT_FALSE(frame.lines.empty());
}

TEST(GroundGrid, RefusesBoundsAndUpItCannotPlace) {
  EXPECT_THROW(dd::planGroundGrid({1, 0, 0}, {0, 1, 1}, {0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(dd::planGroundGrid({0, 0, 0}, {1, NAN, 1}, {0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(dd::planGroundGrid({0, 0, 0}, {1, 1, 1}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(dd::planGroundGrid({0, 0, 0}, {1, 1, 1}, {0, INFINITY, 0}), std::invalid_argument);
}

TEST(GroundGrid, EveryPrimitiveIsOnTheGridLayer) {
  const dd::Frame frame = gridFrame({-1, 0, -2}, {3, 1, 2}, {0, 1, 0});
  EXPECT_EQ(frame.primitiveCount(), frame.lines.size() + frame.arrows.size() + frame.labels.size());
  const dd::Tag grid = dd::tagOf(dd::Layer::Grid);
  for (const auto& line : frame.lines) EXPECT_EQ(line.tag, grid);
  for (const auto& arrow : frame.arrows) EXPECT_EQ(arrow.tag, grid);
  for (const auto& label : frame.labels) EXPECT_EQ(label.tag, grid);
}

TEST(GroundGrid, LinesLieOnThePlaneAtTheBottomOfTheBounds) {
  struct Case {
    Vec3 up;
    int axis;
    double bottom;
  };
  const Vec3 low(-1, -2, -3), high(4, 5, 6);
  for (const Case& c : {Case{{0, 1, 0}, 1, -2}, Case{{0, 0, 1}, 2, -3}, Case{{1, 0, 0}, 0, -1},
                        Case{{0.1, 0.9, -0.2}, 1, -2}, Case{{0, -1, 0}, 1, 5}}) {
    const dd::Frame frame = gridFrame(low, high, c.up);
    ASSERT_FALSE(frame.lines.empty());
    for (const auto& line : frame.lines) {
      EXPECT_DOUBLE_EQ(line.from[c.axis], c.bottom) << c.up.transpose();
      EXPECT_DOUBLE_EQ(line.to[c.axis], c.bottom) << c.up.transpose();
    }
    for (const auto& label : frame.labels) {
      if (label.text.size() > 1) {  // the scale, not the gizmo
        EXPECT_DOUBLE_EQ(label.position[c.axis], c.bottom);
      }
    }
  }
}

TEST(GroundGrid, GizmoArrowsRunAlongTheThreeAxesOneSpacingLong) {
  const dd::GroundGridPlan plan = dd::planGroundGrid({-1, 0, -1}, {1, 2, 1}, {0, 1, 0});
  const dd::Frame frame = gridFrame({-1, 0, -1}, {1, 2, 1}, {0, 1, 0});
  ASSERT_EQ(frame.arrows.size(), 3u);
  for (int axis = 0; axis < 3; ++axis) {
    const dd::Arrow& arrow = frame.arrows[axis];
    EXPECT_TRUE(arrow.from.isApprox(plan.corner));
    EXPECT_TRUE((arrow.to - arrow.from).isApprox(Vec3::Unit(axis) * plan.spacing)) << axis;
  }
  EXPECT_GT(frame.arrows[0].color.r, 0.8f);  // x red, y green, z blue
  EXPECT_GT(frame.arrows[1].color.g, 0.8f);
  EXPECT_GT(frame.arrows[2].color.b, 0.8f);
  int named = 0;
  for (const auto& label : frame.labels)
    for (int axis = 0; axis < 3; ++axis)
      if (label.text == std::string(1, "xyz"[axis])) {
        ++named;
        EXPECT_GT((label.position - plan.corner).dot(Vec3::Unit(axis)), plan.spacing * 0.99);
      }
  EXPECT_EQ(named, 3);
}

TEST(GroundGrid, ScaleLabelsReadInUnitsOfTheSpacing) {
  EXPECT_EQ(dd::groundGridDistance(0, 0.2), "0 m");
  EXPECT_EQ(dd::groundGridDistance(5 * 0.2, 0.2), "1 m");
  EXPECT_EQ(dd::groundGridDistance(5 * 0.1, 0.1), "0.5 m");
  EXPECT_EQ(dd::groundGridDistance(10, 2), "10 m");
  EXPECT_EQ(dd::groundGridDistance(500, 100), "0.5 km");
  EXPECT_EQ(dd::groundGridDistance(5000, 1000), "5 km");
  EXPECT_EQ(dd::groundGridDistance(1e9, 1e8), "1000000 km");
  EXPECT_EQ(dd::groundGridDistance(5 * 0.05, 0.05), "25 cm");
  EXPECT_EQ(dd::groundGridDistance(5 * 0.001, 0.001), "5 mm");
  const dd::Frame frame = gridFrame({0, 0, 0}, {16, 1, 4}, {0, 1, 0});  // 1 m spacing, longer along x
  std::vector<std::string> scale;
  for (const auto& label : frame.labels)
    if (label.text.size() > 1) scale.push_back(label.text);
  EXPECT_EQ(scale, (std::vector<std::string>{"0 m", "5 m", "10 m", "15 m"}));
}

}  // namespace
