#include "cli/accuracy_plots.h"

#include <algorithm>

#include "cli/output_folder.h"
#include "render/renderer.h"
#include "viewer/line_plot.h"

namespace physdbg::cli {

void writeAccuracyPlot(render::Renderer& renderer, const std::filesystem::path& png, const std::string& reference,
                       const reports::AccuracyMethods& methods) {
  std::vector<viewer::PlotSeries> series;
  for (const auto& [method, samples] : methods) {
    viewer::PlotSeries curve{method, viewer::plotColor(series.size()), {}, {}, true};
    for (const reports::AccuracySample& sample : samples) {
      curve.x.push_back(sample.milliseconds);
      curve.values.push_back(std::max(sample.error, smallestPlottedError));
    }
    series.push_back(std::move(curve));
  }
  const viewer::PlotLayout layout{reference + ": work-precision (errors below 1e-16 drawn at 1e-16)",
                                  {"run time (ms)", true},
                                  {"error", true}};
  writeOutputPng(png.string(), viewer::renderLinePlot(renderer, layout, series), "-o");
}

}  // namespace physdbg::cli
