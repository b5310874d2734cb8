#include "viewer/line_plot.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "render/renderer.h"
#include "render/text_geometry.h"
#include "viewer/pixel_canvas.h"
#include "viewer/plot_axis.h"

namespace physdbg::viewer {
namespace {

namespace dd = debugdraw;
constexpr dd::Color axisColor{0.85f, 0.85f, 0.85f, 1.0f};
constexpr dd::Color gridColor{0.3f, 0.3f, 0.34f, 1.0f};
constexpr float labelScale = 1.5f, titleScale = 2.0f;
constexpr std::size_t maxLegendCharacters = 40;

float textWidth(const std::string& text, float scale) {
  const std::array<float, 4> extent = render::textExtent({0, 0, scale, text, axisColor});
  return extent[2] - extent[0];
}

// The pixel rectangle of the chart itself, inside the labels.
struct Chart {
  double left, right, top, bottom;
};

double xOf(const PlotSeries& series, std::size_t i) {
  return series.x.empty() ? static_cast<double>(i + 1) : series.x[i];
}

std::string legendName(const std::string& name) {
  return name.size() <= maxLegendCharacters ? name : name.substr(0, maxLegendCharacters - 3) + "...";
}

Chart chartRectangle(const PlotArea& area, const PlotAxisScale& yAxis, const std::vector<PlotSeries>& series) {
  float tickWidth = 0, legendWidth = 0;
  for (const PlotTick& tick : yAxis.ticks()) tickWidth = std::max(tickWidth, textWidth(tick.label, labelScale));
  for (const PlotSeries& one : series) legendWidth = std::max(legendWidth, textWidth(legendName(one.name), labelScale));
  const Chart chart{area.left + tickWidth + 16, area.left + area.width - legendWidth - 40, area.top + 52,
                    area.top + area.height - 44};
  if (chart.right - chart.left < 60 || chart.bottom - chart.top < 60)
    throw std::invalid_argument("line plot: area too small for its labels and legend");
  return chart;
}

void drawAxes(const PlotLayout& layout, const PlotAxisScale& xAxis, const PlotAxisScale& yAxis, const Chart& chart,
              const PlotArea& area, dd::Frame& frame) {
  const auto text = [&](double x, double y, float scale, const std::string& value) {
    frame.texts.push_back({static_cast<float>(x), static_cast<float>(y), scale, value, axisColor});
  };
  text(area.left + 8, area.top + 6, titleScale, layout.title);
  text(area.left + 8, chart.top - 20, labelScale, layout.y.label + (layout.y.logarithmic ? " (log scale)" : ""));
  for (const PlotTick& tick : yAxis.ticks()) {
    const double y = chart.bottom - (chart.bottom - chart.top) * yAxis.fraction(tick.value);
    frame.lines.push_back({pixelPoint(chart.left, y), pixelPoint(chart.right, y), gridColor});
    text(chart.left - 8 - textWidth(tick.label, labelScale), y - 5, labelScale, tick.label);
  }
  for (const PlotTick& tick : xAxis.ticks()) {
    const double x = chart.left + (chart.right - chart.left) * xAxis.fraction(tick.value);
    frame.lines.push_back({pixelPoint(x, chart.top), pixelPoint(x, chart.bottom), gridColor});
    frame.lines.push_back({pixelPoint(x, chart.bottom), pixelPoint(x, chart.bottom + 5), axisColor});
    text(x - 0.5 * textWidth(tick.label, labelScale), chart.bottom + 8, labelScale, tick.label);
  }
  frame.lines.push_back({pixelPoint(chart.left, chart.top), pixelPoint(chart.left, chart.bottom), axisColor});
  frame.lines.push_back({pixelPoint(chart.left, chart.bottom), pixelPoint(chart.right, chart.bottom), axisColor});
  const std::string xLabel = layout.x.label + (layout.x.logarithmic ? " (log scale)" : "");
  text(0.5 * (chart.left + chart.right - textWidth(xLabel, labelScale)), chart.bottom + 26, labelScale, xLabel);
}

// A polyline two pixels wide (the second one pixel lower), so it reads
// over grid lines; broken where a point cannot be shown.
void drawSeries(const PlotSeries& series, const PlotAxisScale& xAxis, const PlotAxisScale& yAxis, const Chart& chart,
                dd::Frame& frame) {
  const auto point = [&](std::size_t i, double offset) {
    return pixelPoint(chart.left + (chart.right - chart.left) * xAxis.fraction(xOf(series, i)),
                      chart.bottom - (chart.bottom - chart.top) * yAxis.fraction(series.values[i]) + offset);
  };
  const auto shown = [&](std::size_t i) { return xAxis.shows(xOf(series, i)) && yAxis.shows(series.values[i]); };
  for (std::size_t i = 0; i < series.values.size(); ++i) {
    if (!shown(i)) continue;
    if (series.markers) {
      const dd::Vec3 centre = point(i, 0);
      frame.boxes.push_back(pixelRectangle(centre.x(), -centre.y(), 3, 3, series.color));
    }
    if (i == 0 || !shown(i - 1)) continue;
    for (const double offset : {0.0, 1.0}) frame.lines.push_back({point(i - 1, offset), point(i, offset), series.color});
  }
}

void drawLegend(const std::vector<PlotSeries>& series, const Chart& chart, dd::Frame& frame) {
  for (std::size_t s = 0; s < series.size(); ++s) {
    const double y = chart.top + 4 + 20.0 * static_cast<double>(s);
    frame.boxes.push_back(pixelRectangle(chart.right + 20, y + 6, 8, 2, series[s].color));
    frame.texts.push_back({static_cast<float>(chart.right + 32), static_cast<float>(y), labelScale,
                           legendName(series[s].name), series[s].color});
  }
}

std::vector<double> allValues(const std::vector<PlotSeries>& series, bool x) {
  std::vector<double> values;
  for (const PlotSeries& one : series)
    for (std::size_t i = 0; i < one.values.size(); ++i) values.push_back(x ? xOf(one, i) : one.values[i]);
  return values;
}

}  // namespace

dd::Color plotColor(std::size_t index) {
  static constexpr std::array<dd::Color, 8> palette{{{1.0f, 0.6f, 0.1f, 1},
                                                    {0.4f, 0.7f, 1.0f, 1},
                                                    {0.5f, 0.9f, 0.4f, 1},
                                                    {1.0f, 0.4f, 0.6f, 1},
                                                    {0.9f, 0.9f, 0.3f, 1},
                                                    {0.7f, 0.5f, 1.0f, 1},
                                                    {0.3f, 0.9f, 0.9f, 1},
                                                    {0.9f, 0.9f, 0.9f, 1}}};
  return palette[index % palette.size()];
}

void drawLinePlot(const PlotLayout& layout, const std::vector<PlotSeries>& series, const PlotArea& area,
                  dd::Frame& frame) {
  for (const PlotSeries& one : series)
    if (!one.x.empty() && one.x.size() != one.values.size())
      throw std::invalid_argument("line plot: series '" + one.name + "' has " + std::to_string(one.x.size()) +
                                  " x values and " + std::to_string(one.values.size()) + " y values");
  const PlotAxisScale xAxis(allValues(series, true), layout.x.logarithmic);
  const PlotAxisScale yAxis(allValues(series, false), layout.y.logarithmic);
  const Chart chart = chartRectangle(area, yAxis, series);
  drawAxes(layout, xAxis, yAxis, chart, area, frame);
  for (const PlotSeries& one : series) drawSeries(one, xAxis, yAxis, chart, frame);
  drawLegend(series, chart, frame);
}

render::Image renderLinePlot(render::Renderer& renderer, const PlotLayout& layout,
                             const std::vector<PlotSeries>& series) {
  const int width = renderer.options().width, height = renderer.options().height;
  dd::Frame frame;
  drawLinePlot(layout, series, {0, 0, double(width), double(height)}, frame);
  return renderer.render(frame, pixelCamera(width, height));
}

}  // namespace physdbg::viewer
