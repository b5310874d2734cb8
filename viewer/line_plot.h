#pragma once
// A line chart drawn with debug-draw lines and text on a pixel canvas (see
// pixel_canvas.h), so plots need no gnuplot and render like every frame.
#include <string>
#include <vector>

#include "debugdraw/primitives.h"

namespace physdbg::viewer {

struct PlotSeries {
  std::string name;
  debugdraw::Color color;
  std::vector<double> values;  // y at x = 1, 2, ...
};

struct PlotArea {
  double left = 0, top = 0, width = 0, height = 0;  // pixels, including labels
};

// Axes from 0 to the largest value (x) and from 0 to the largest y, with
// labelled ticks and a legend. Non-finite values are skipped. Throws
// std::invalid_argument for an area too small to hold the labels.
void drawLinePlot(const std::string& title, const std::string& xLabel, const std::vector<PlotSeries>& series,
                  const PlotArea& area, debugdraw::Frame& frame);

}  // namespace physdbg::viewer
