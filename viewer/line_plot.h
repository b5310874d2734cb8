#pragma once
// The one plotter of physdbg: every chart (tree SAR/height, accuracy
// work-precision, simulate --series) is drawn here, with debug-draw lines
// and text on a pixel canvas (see pixel_canvas.h), so plots need no gnuplot,
// look alike, and render like every frame.
#include <string>
#include <vector>

#include "debugdraw/primitives.h"
#include "render/image.h"

namespace physdbg::render {
class Renderer;
}

namespace physdbg::viewer {

struct PlotSeries {
  std::string name;
  debugdraw::Color color;
  std::vector<double> values;  // y
  std::vector<double> x;       // empty: x = 1, 2, ... (index + 1)
  bool markers = false;        // a square at each point: sweeps of a few points
};

struct PlotAxis {
  std::string label;
  bool logarithmic = false;
};

struct PlotLayout {
  std::string title;
  PlotAxis x, y;
};

struct PlotArea {
  double left = 0, top = 0, width = 0, height = 0;  // pixels, including labels
};

// The n-th of a palette of colours that stay apart on the dark background.
debugdraw::Color plotColor(std::size_t index);

// Title, both axes with labelled ticks and grid lines, each series as a
// polyline and a legend naming them. Points an axis cannot show (non-finite;
// not positive on a log axis) are left out and break the line. Throws
// std::invalid_argument for an area too small to hold the labels, or series
// whose x and y differ in length.
void drawLinePlot(const PlotLayout& layout, const std::vector<PlotSeries>& series, const PlotArea& area,
                  debugdraw::Frame& frame);

// The plot alone, filling the renderer's image.
render::Image renderLinePlot(render::Renderer& renderer, const PlotLayout& layout,
                             const std::vector<PlotSeries>& series);

}  // namespace physdbg::viewer
