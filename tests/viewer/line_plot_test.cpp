// The one plotter: lines land where their values say, on linear and log
// axes; the legend and title are drawn; tick labels are short and exact.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "viewer/line_plot.h"
#include "viewer/plot_axis.h"

namespace physdbg::viewer {
namespace {

using render::testing::isBackground;
using render::testing::Pixel;
using render::testing::pixelAt;

constexpr int width = 400, height = 300;
// drawLinePlot's chart spans rows 52 (top) to height - 44 (bottom).
constexpr int chartTop = 52, chartBottom = height - 44, middleRow = (chartTop + chartBottom) / 2;

bool isRed(const Pixel& p) { return p[0] > 200 && p[1] < 60 && p[2] < 60; }

// Rows holding a red pixel in columns [x0, x1).
std::vector<int> redRows(const render::Image& image, int x0, int x1) {
  std::vector<int> rows;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x)
      if (isRed(pixelAt(image, x, y))) {
        rows.push_back(y);
        break;
      }
  return rows;
}

render::Image plot(const PlotLayout& layout, const std::vector<PlotSeries>& series) {
  render::Renderer renderer({width, height});
  return renderLinePlot(renderer, layout, series);
}

// y = 5 on an axis from 0 to 10 (the other series sets the range) is the
// chart's middle row; the legend's red swatch sits right of the chart.
TEST(LinePlot, HorizontalLineLandsAtItsValueAndTheLegendNamesIt) {
  const PlotSeries flat{"flat", {1, 0, 0, 1}, {5, 5, 5}, {0, 5, 10}, false};
  const PlotSeries rising{"rising", {0.3f, 0.6f, 1, 1}, {0, 10}, {0, 10}, false};
  const render::Image image = plot({"known lines", {"x"}, {"y"}}, {flat, rising});
  const std::vector<int> rows = redRows(image, 150, 250);
  ASSERT_FALSE(rows.empty());
  for (const int row : rows) EXPECT_NEAR(row, middleRow, 2);
  const std::vector<int> legend = redRows(image, 320, width);
  ASSERT_FALSE(legend.empty());
  EXPECT_LT(legend.front(), chartTop + 20);
  int title = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < width; ++x) title += isBackground(pixelAt(image, x, y)) ? 0 : 1;
  EXPECT_GT(title, 50);
}

// On a log axis from 1e-3 to 1e3, 1 is the middle; values that are not
// positive are left out instead of breaking the plot.
TEST(LinePlot, LogAxisPutsOneHalfwayBetweenAThousandthAndAThousand) {
  const PlotSeries one{"one", {1, 0, 0, 1}, {1, 1, 0, 1}, {1, 2, 3, 4}, true};
  const PlotSeries span{"span", {0.3f, 0.6f, 1, 1}, {1e-3, 1e3}, {1, 4}, false};
  const render::Image image = plot({"log", {"x"}, {"y", true}}, {one, span});
  const std::vector<int> rows = redRows(image, 150, 250);
  ASSERT_FALSE(rows.empty());
  for (const int row : rows) EXPECT_NEAR(row, middleRow, 4);
}

TEST(LinePlot, RefusesMismatchedSeriesAndTooSmallAreas) {
  debugdraw::Frame frame;
  EXPECT_THROW(drawLinePlot({}, {{"bad", {1, 0, 0, 1}, {1, 2}, {1}, false}}, {0, 0, 400, 300}, frame),
               std::invalid_argument);
  EXPECT_THROW(drawLinePlot({}, {{"a", {1, 0, 0, 1}, {1, 2}, {}, false}}, {0, 0, 60, 60}, frame),
               std::invalid_argument);
}

TEST(PlotAxis, TicksAreRoundAndLabelsShort) {
  const PlotAxisScale linear({0.013, 0.27}, false);
  std::vector<std::string> labels;
  for (const PlotTick& tick : linear.ticks()) labels.push_back(tick.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"0", "0.1", "0.2", "0.3"}));
  const PlotAxisScale logarithmic({3e-12, 0.0, -1.0, 2e-4}, true);
  labels.clear();
  for (const PlotTick& tick : logarithmic.ticks()) labels.push_back(tick.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"1e-12", "1e-10", "1e-8", "1e-6", "0.0001", "0.01"}));
  EXPECT_FALSE(logarithmic.shows(0.0));
  const PlotAxisScale exact({1e-16, 1e-16}, true);  // clamped round-off errors: in the middle, not on the axis
  EXPECT_DOUBLE_EQ(exact.fraction(1e-16), 0.5);
  EXPECT_EQ(tickLabel(2e6), "2e6");
  EXPECT_EQ(tickLabel(-1e-15 * 0), "0");
  EXPECT_EQ(tickLabel(2.5e-5), "2.5e-5");
}

}  // namespace
}  // namespace physdbg::viewer
