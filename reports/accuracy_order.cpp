// Convergence orders for the accuracy summary. A slope is printed only where
// it says something about dt: a method exact to round-off has no order (it
// is better than any), and a series whose error does not fall steadily with
// dt has a slope that would mislead, so the summary says what it saw.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reports/accuracy_report.h"

namespace physdbg::reports {
namespace {

// One number in a printf format ("%.3g" for errors, "%.2f" for orders).
std::string printed(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string number(double value) { return printed("%.3g", value); }

// "1/120": the report's time steps are whole rates.
std::string stepText(double dt) { return printed("1/%.0f", 1.0 / dt); }

// Below this slope the error is not falling with dt (a floor set by
// something else: contact slop, a tolerance, a restitution threshold).
constexpr double flatSlope = 0.2;
// A finer step may lose this share to noise before the series counts as rising.
constexpr double riseSlack = 1.05;

}  // namespace

double fittedOrder(const std::vector<AccuracySample>& samples) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const AccuracySample& sample : samples) {
    if (!(sample.error > roundOffError) || !(sample.parameter > 0.0)) continue;
    const double x = std::log(sample.parameter), y = std::log(sample.error);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator <= 0.0) return std::nan("");
  return (n * sxy - sx * sy) / denominator;
}

OrderFit fitOrder(const std::vector<AccuracySample>& samples) {
  std::vector<AccuracySample> coarseToFine = samples;
  std::stable_sort(coarseToFine.begin(), coarseToFine.end(),
                   [](const AccuracySample& a, const AccuracySample& b) { return a.parameter > b.parameter; });
  double largest = 0;
  std::vector<const AccuracySample*> above;
  for (const AccuracySample& sample : coarseToFine) {
    largest = std::max(largest, sample.error);
    if (sample.error > roundOffError) above.push_back(&sample);
  }
  const double nan = std::nan("");
  if (above.empty()) return {nan, "exact (error at round-off, at most " + number(largest) + ", for every dt)"};
  if (above.size() < 2)
    return {nan, "none: only dt " + stepText(above.front()->parameter) + " has an error above round-off (" +
                     number(above.front()->error) + ")"};
  for (std::size_t i = 1; i < above.size(); ++i)
    if (above[i]->error > riseSlack * above[i - 1]->error)
      return {nan, "none: not monotone, error rises from " + number(above[i - 1]->error) + " at dt " +
                       stepText(above[i - 1]->parameter) + " to " + number(above[i]->error) + " at dt " +
                       stepText(above[i]->parameter)};
  const double order = fittedOrder(samples);
  if (order < flatSlope)
    return {nan, "none: error does not fall with dt (" + number(above.front()->error) + " to " +
                     number(above.back()->error) + ", slope " + number(order) + ")"};
  return {order, printed("%.2f", order)};
}

}  // namespace physdbg::reports
