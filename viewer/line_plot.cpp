#include "viewer/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "viewer/pixel_canvas.h"

namespace physdbg::viewer {
namespace {

namespace dd = debugdraw;
constexpr dd::Color axisColor{0.8f, 0.8f, 0.8f, 1.0f};
constexpr dd::Color gridColor{0.3f, 0.3f, 0.34f, 1.0f};

// 1, 2 or 5 times a power of ten, so that about five ticks cover `range`.
double tickStep(double range) {
  const double raw = range / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0})
    if (factor * power >= raw) return factor * power;
  return 10.0 * power;
}

std::string formatTick(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void drawLinePlot(const std::string& title, const std::string& xLabel, const std::vector<PlotSeries>& series,
                  const PlotArea& area, dd::Frame& frame) {
  const double left = area.left + 60, right = area.left + area.width - 150;
  const double top = area.top + 30, bottom = area.top + area.height - 40;
  if (right - left < 50 || bottom - top < 50) throw std::invalid_argument("line plot: area too small");
  double xMax = 1, yMax = 0;
  for (const PlotSeries& one : series) {
    xMax = std::max(xMax, static_cast<double>(one.values.size()));
    for (const double value : one.values)
      if (std::isfinite(value)) yMax = std::max(yMax, value);
  }
  if (yMax <= 0) yMax = 1;
  const double xStep = tickStep(xMax), yStep = tickStep(yMax);
  yMax = std::ceil(yMax / yStep) * yStep;
  auto px = [&](double x) { return left + (right - left) * x / xMax; };
  auto py = [&](double y) { return bottom - (bottom - top) * y / yMax; };

  frame.texts.push_back({static_cast<float>(left), static_cast<float>(area.top + 6), 2, title, axisColor});
  for (double y = 0; y <= yMax + 0.5 * yStep; y += yStep) {
    frame.lines.push_back({pixelPoint(left, py(y)), pixelPoint(right, py(y)), y == 0 ? axisColor : gridColor});
    frame.texts.push_back({static_cast<float>(area.left + 4), static_cast<float>(py(y) - 6), 1.5f, formatTick(y),
                           axisColor});
  }
  for (double x = 0; x <= xMax; x += xStep) {
    frame.lines.push_back({pixelPoint(px(x), bottom), pixelPoint(px(x), bottom + 5), axisColor});
    frame.texts.push_back({static_cast<float>(px(x) - 6), static_cast<float>(bottom + 8), 1.5f, formatTick(x),
                           axisColor});
  }
  frame.lines.push_back({pixelPoint(left, top), pixelPoint(left, bottom), axisColor});
  frame.texts.push_back({static_cast<float>(0.5 * (left + right) - 40), static_cast<float>(bottom + 24), 1.5f,
                         xLabel, axisColor});
  for (std::size_t s = 0; s < series.size(); ++s) {
    const PlotSeries& one = series[s];
    for (std::size_t i = 1; i < one.values.size(); ++i) {
      if (!std::isfinite(one.values[i - 1]) || !std::isfinite(one.values[i])) continue;
      frame.lines.push_back({pixelPoint(px(static_cast<double>(i)), py(one.values[i - 1])),
                             pixelPoint(px(static_cast<double>(i + 1)), py(one.values[i])), one.color});
    }
    const double legendY = top + 20.0 * s;
    frame.boxes.push_back(pixelRectangle(right + 20, legendY + 6, 8, 3, one.color));
    frame.texts.push_back({static_cast<float>(right + 34), static_cast<float>(legendY), 1.5f, one.name, one.color});
  }
}

}  // namespace physdbg::viewer
