#include "cli/solver_plots.h"

#include <algorithm>

#include "cli/output_folder.h"
#include "render/renderer.h"
#include "viewer/line_plot.h"

namespace physdbg::cli {
namespace {

// One engine's points in the order of the work asked for (substeps x
// iterations, then substeps): the line follows the knob, and timing noise
// moves points sideways instead of tangling the line.
std::vector<reports::SolverPoint> pointsOf(const std::vector<reports::SolverPoint>& points, const std::string& engine) {
  std::vector<reports::SolverPoint> out;
  for (const auto& point : points) {
    if (point.engine == engine) out.push_back(point);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const int workA = a.substeps * a.iterations, workB = b.substeps * b.iterations;
    return workA != workB ? workA < workB : a.substeps < b.substeps;
  });
  return out;
}

viewer::PlotSeries series(const std::string& name, std::size_t color, const std::vector<reports::SolverPoint>& points,
                          double reports::SolverMeasure::*figure) {
  viewer::PlotSeries curve{name, viewer::plotColor(color), {}, {}, true};
  for (const auto& point : points) {
    curve.x.push_back(point.measure.msPerStep);
    curve.values.push_back(std::max(point.measure.*figure, smallestPlottedLength));
  }
  return curve;
}

}  // namespace

void writeSolverPlot(render::Renderer& renderer, const std::filesystem::path& png, const std::string& scene,
                     const std::vector<reports::SolverPoint>& points) {
  std::vector<viewer::PlotSeries> curves;
  std::vector<std::string> engines;
  for (const auto& point : points) {
    if (std::find(engines.begin(), engines.end(), point.engine) == engines.end()) engines.push_back(point.engine);
  }
  for (const std::string& engine : engines) {
    const auto own = pointsOf(points, engine);
    curves.push_back(series(engine + " penetration", curves.size(), own, &reports::SolverMeasure::largestPenetration));
    curves.push_back(series(engine + " drift", curves.size(), own, &reports::SolverMeasure::drift));
  }
  const viewer::PlotLayout layout{scene + ": solver work-precision (values below 1e-7 m drawn at 1e-7)",
                                  {"ms per step", true},
                                  {"largest penetration, drift (m)", true}};
  writeOutputPng(png.string(), viewer::renderLinePlot(renderer, layout, curves), "-o");
}

}  // namespace physdbg::cli
