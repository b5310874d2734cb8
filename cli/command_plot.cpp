// physdbg plot FILE.csv --y COLUMNS -o FILE.png: columns of a CSV of numbers
// (simulate --series, a report's CSV) drawn by the project's one plotter.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/numeric_csv.h"
#include "cli/output_folder.h"
#include "render/renderer.h"
#include "viewer/line_plot.h"

namespace physdbg::cli {
namespace {

// Rows held in memory (each column a double), and curves in one plot.
constexpr long long maxPlotRows = 1'000'000;
constexpr std::size_t maxPlotColumns = 8;
// More points than this per curve are thinned to each bucket's lowest and
// highest value, in order: spikes stay visible, the drawing stays small.
constexpr std::size_t maxDrawnPoints = 4096;

std::vector<std::string> columnList(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream stream(list);
  for (std::string name; std::getline(stream, name, ',');) names.push_back(name);
  if (names.empty() || list.back() == ',' || std::count(names.begin(), names.end(), "") > 0)
    throw UsageError("--y: expected COLUMN[,COLUMN...], got '" + list + "'");
  if (names.size() > maxPlotColumns) throw UsageError("--y: at most " + std::to_string(maxPlotColumns) + " columns");
  return names;
}

std::size_t requireColumn(const NumericCsv& csv, const std::string& option, const std::string& name) {
  const int index = csv.columnIndex(name);
  if (index >= 0) return static_cast<std::size_t>(index);
  std::string known;
  for (const std::string& column : csv.columns()) known += (known.empty() ? "" : ", ") + column;
  throw UsageError(option + ": '" + name + "' is not a column of " + csv.path() + " (it has " + known + ")");
}

// Per bucket of consecutive points, the lowest and the highest, in x order.
viewer::PlotSeries thinned(viewer::PlotSeries series) {
  const std::size_t count = series.values.size();
  if (count <= maxDrawnPoints) return series;
  const std::size_t buckets = maxDrawnPoints / 2;
  viewer::PlotSeries out{series.name, series.color, {}, {}, false};
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = b * count / buckets, end = (b + 1) * count / buckets;
    const auto [low, high] = std::minmax_element(series.values.begin() + static_cast<long>(begin),
                                                 series.values.begin() + static_cast<long>(end));
    for (const auto which : {std::min(low, high), std::max(low, high)}) {
      const std::size_t i = static_cast<std::size_t>(which - series.values.begin());
      out.x.push_back(series.x[i]);
      out.values.push_back(series.values[i]);
    }
  }
  return out;
}

std::vector<viewer::PlotSeries> readSeries(NumericCsv& csv, std::size_t xColumn,
                                           const std::vector<std::string>& names) {
  std::vector<std::size_t> columns;
  std::vector<viewer::PlotSeries> series;
  for (const std::string& name : names) {
    columns.push_back(requireColumn(csv, "--y", name));
    series.push_back({name, viewer::plotColor(series.size()), {}, {}, false});
  }
  std::vector<double> row;
  for (long long rows = 1; csv.next(row); ++rows) {
    if (rows > maxPlotRows) csv.fail("more than " + std::to_string(maxPlotRows) + " rows to plot");
    for (std::size_t s = 0; s < series.size(); ++s) {
      series[s].x.push_back(row[xColumn]);
      series[s].values.push_back(row[columns[s]]);
    }
  }
  if (series.front().values.empty()) csv.fail("no rows to plot after the header");
  for (viewer::PlotSeries& one : series) one = thinned(std::move(one));
  return series;
}

}  // namespace

int runPlot(const std::vector<std::string>& args) {
  CommandSpec spec{
      "plot",
      "FILE.csv --y COLUMN[,COLUMN...] [--x COLUMN] [--log-x] [--log-y] [--title TEXT] -o FILE.png",
      "Draws columns of a CSV of numbers with a header line (simulate --series, simulate --trace, a report's\n"
      "CSV) against one column, with labelled ticks and a legend. On a log axis, values that are not positive\n"
      "are left out (the line breaks there).",
      {{"--y", "", "COLUMNS", "comma list of up to 8 columns to draw"},
       {"--x", "", "COLUMN", "the column along x (default: the first column)"},
       {"--log-x", "", "", "logarithmic x axis"},
       {"--log-y", "", "", "logarithmic y axis"},
       {"--title", "", "TEXT", "title (default: the file name)"},
       outputOption("FILE.png", "the picture to write")},
      1,
      1};
  addOptions(spec, {OptionGroup::Backend});
  spec.options.push_back({"--size", "", "WxH", "image size in pixels (default 960x600)"});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  if (!parsed->has("--y")) throw UsageError("--y COLUMNS is required");
  const std::string output = requiredOutput(*parsed, "FILE.png");
  checkOutputFile(output, "-o");
  const auto [width, height] = readSize(*parsed, "960x600");
  NumericCsv csv(parsed->positional()[0]);
  const std::string xName = parsed->value("--x", csv.columns().front());
  const std::vector<viewer::PlotSeries> series =
      readSeries(csv, requireColumn(csv, "--x", xName), columnList(parsed->value("--y")));
  const viewer::PlotLayout layout{parsed->value("--title", csv.path()),
                                  {xName, parsed->has("--log-x")},
                                  {parsed->value("--y"), parsed->has("--log-y")}};
  render::Renderer renderer({width, height, 0, readBackend(*parsed)});
  writeOutputPng(output, asUsageError([&] { return viewer::renderLinePlot(renderer, layout, series); }), "-o");
  std::printf("wrote %s: %s against %s\n", output.c_str(), parsed->value("--y").c_str(), xName.c_str());
  return 0;
}

}  // namespace physdbg::cli
