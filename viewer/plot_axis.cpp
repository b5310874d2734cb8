#include "viewer/plot_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace physdbg::viewer {
namespace {

// 1, 2 or 5 times a power of ten, so that about five ticks cover `range`.
double tickStep(double range) {
  const double raw = range / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0})
    if (factor * power >= raw * (1 - 1e-9)) return factor * power;
  return 10.0 * power;
}

// "1e+06" -> "1e6", "2.5e-05" -> "2.5e-5".
std::string shortExponent(std::string text) {
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string exponent = text.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return text.substr(0, e + 1) + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
}

}  // namespace

std::string tickLabel(double value) {
  if (value == 0) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return shortExponent(text);
}

PlotAxisScale::PlotAxisScale(const std::vector<double>& values, bool logarithmic) : logarithmic_(logarithmic) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const double value : values) {
    if (!shows(value)) continue;
    const double position = logarithmic ? std::log10(value) : value;
    low = std::min(low, position);
    high = std::max(high, position);
  }
  if (!(low <= high)) low = 0, high = 1;
  if (logarithmic) logarithmicTicks(low, high);
  else linearTicks(low, high);
}

bool PlotAxisScale::shows(double value) const { return std::isfinite(value) && (!logarithmic_ || value > 0); }

double PlotAxisScale::fraction(double value) const {
  const double position = logarithmic_ ? std::log10(value) : value;
  return (position - low_) / (high_ - low_);
}

// Zero joins the range when the values sit closer to it than they spread
// (counts, energies that start at rest), so small changes do not look large.
void PlotAxisScale::linearTicks(double low, double high) {
  if (low > 0 && low < high - low) low = 0;
  if (high < 0 && -high < high - low) high = 0;
  if (high - low <= 1e-12 * std::max(std::abs(low), std::abs(high))) {
    const double spread = low == 0 ? 1 : 0.1 * std::abs(low);
    low -= spread;
    high += spread;
  }
  const double step = tickStep(high - low);
  low_ = std::floor(low / step + 1e-9) * step;
  high_ = std::ceil(high / step - 1e-9) * step;
  for (long long i = 0; low_ + step * static_cast<double>(i) <= high_ + 0.5 * step; ++i) {
    double value = low_ + step * static_cast<double>(i);
    if (std::abs(value) < 1e-9 * step) value = 0;
    ticks_.push_back({value, tickLabel(value)});
  }
}

// Whole decades, at most about eight labelled.
void PlotAxisScale::logarithmicTicks(double low, double high) {
  low_ = std::floor(low);
  high_ = std::ceil(high);
  // Values all on one power of ten: a decade either side, so they do not
  // hide in the axis line.
  if (high_ - low_ < 1) --low_, ++high_;
  const int every = static_cast<int>(std::ceil((high_ - low_) / 8.0));
  high_ = low_ + every * std::ceil((high_ - low_) / every);  // the top is labelled too
  for (double decade = low_; decade <= high_; decade += every)
    ticks_.push_back({std::pow(10.0, decade), tickLabel(std::pow(10.0, decade))});
}

}  // namespace physdbg::viewer
