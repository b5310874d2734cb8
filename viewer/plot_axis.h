#pragma once
// One axis of a line plot: the range it shows, where a value lands on it and
// its labelled ticks. Linear axes tick at 1, 2 or 5 times a power of ten;
// logarithmic ones at powers of ten. Labels are short ("0.5", "2e6",
// "1e-12"), so they fit beside a small chart and read the same in every plot.
#include <string>
#include <vector>

namespace physdbg::viewer {

struct PlotTick {
  double value = 0;
  std::string label;
};

class PlotAxisScale {
 public:
  // The range covers every finite value (positive ones only when
  // logarithmic), rounded out to whole ticks. Without any such value the
  // axis shows 0..1 (1..10 when logarithmic).
  PlotAxisScale(const std::vector<double>& values, bool logarithmic);

  bool logarithmic() const { return logarithmic_; }
  // Whether a value can be drawn (finite; positive on a log axis).
  bool shows(double value) const;
  // 0 at the low end of the range, 1 at the high end.
  double fraction(double value) const;
  const std::vector<PlotTick>& ticks() const { return ticks_; }

 private:
  void linearTicks(double low, double high);
  void logarithmicTicks(double low, double high);

  bool logarithmic_;
  double low_ = 0, high_ = 1;  // log10 of the range when logarithmic
  std::vector<PlotTick> ticks_;
};

// "%g"-like and short: 0, 0.25, 1500, 2e6, 1e-12 (no "e+06", no "-0").
std::string tickLabel(double value);

}  // namespace physdbg::viewer
