// Files and summary of the accuracy report. Plots are drawn by gnuplot when
// it is on the PATH; without it the CSV files still carry every figure.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "reports/accuracy_report.h"
#include "reports/child_process.h"

namespace physdbg::reports {
namespace {

using Grouped = std::map<std::string, std::map<std::string, std::vector<AccuracySample>>>;

// Ordered by reference then method name: std::map keeps runs repeatable.
Grouped group(const std::vector<AccuracySample>& samples) {
  Grouped grouped;
  for (const AccuracySample& sample : samples) grouped[sample.reference][sample.method].push_back(sample);
  return grouped;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

bool isTimeStep(const std::string& reference) { return reference.rfind("depth_", 0) != 0; }

void writeCsv(const std::filesystem::path& directory, const std::string& reference,
              const std::map<std::string, std::vector<AccuracySample>>& methods) {
  std::string text = std::string("method,") + (isTimeStep(reference) ? "dt" : "tolerance") + ",error,ms,note\n";
  for (const auto& [method, samples] : methods) {
    for (const AccuracySample& s : samples) {
      char line[256];
      std::snprintf(line, sizeof line, "%s,%.10g,%.10g,%.6g,%s\n", method.c_str(), s.parameter, s.error,
                    s.milliseconds, s.note.c_str());
      text += line;
    }
  }
  writeFile(directory / (reference + ".csv"), text);
}

// gnuplot runs in `directory` (the script names its files relative to it),
// with an argument vector: no shell ever sees the folder name.
bool drawWithGnuplot(const std::filesystem::path& directory, const std::string& script) {
  if (!findExecutable("gnuplot")) return false;
  try {
    return runChild({"gnuplot", {"./" + script}, directory.string(), true}).succeeded();
  } catch (const std::runtime_error&) {
    return false;
  }
}

// One data block per method (gnuplot's `index`), errors clamped to 1e-16 so
// exact results still appear on the log scale.
bool writePlot(const std::filesystem::path& directory, const std::string& reference,
               const std::map<std::string, std::vector<AccuracySample>>& methods) {
  std::string data, plot;
  int index = 0;
  for (const auto& [method, samples] : methods) {
    for (const AccuracySample& s : samples) {
      data += number(std::max(s.milliseconds, 1e-6)) + " " + number(std::max(s.error, 1e-16)) + "\n";
    }
    data += "\n\n";
    plot += std::string(index ? ", " : "plot ") + "'" + reference + ".dat' index " + std::to_string(index) +
            " with linespoints title '" + method + "'";
    ++index;
  }
  writeFile(directory / (reference + ".dat"), data);
  writeFile(directory / (reference + ".gp"),
            "set terminal pngcairo noenhanced size 900,600\nset output '" + reference +
                ".png'\nset logscale xy\nset format y '%g'\nset xlabel 'run time (ms)'\nset ylabel 'error'\nset title '" + reference +
                ": work-precision'\nset key bottom left\nset grid\n" + plot + "\n");
  return drawWithGnuplot(directory, reference + ".gp");
}

std::string summaryTable(const Grouped& grouped) {
  std::string text =
      "| reference | method | fitted order | error (coarsest) | error (finest) | ms (finest) | note (finest) |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& [reference, methods] : grouped) {
    for (const auto& [method, samples] : methods) {
      const AccuracySample &coarsest = samples.front(), &finest = samples.back();
      const std::string order = isTimeStep(reference) ? number(fittedOrder(samples)) : "n/a";
      text += "| " + reference + " | " + method + " | " + order + " | " + number(coarsest.error) + " | " +
              number(finest.error) + " | " + number(finest.milliseconds) + " | " + finest.note + " |\n";
    }
  }
  return text;
}

}  // namespace

std::string runAccuracyReport(const AccuracyOptions& options, const std::function<void(const std::string&)>& progress) {
  const Grouped grouped = group(runAccuracySweep(options.quick, progress));
  std::string summary = "# Accuracy\n\nTime-step references: dt from 1/30 s to 1/" +
                        std::string(options.quick ? "240" : "3840") +
                        " s; the order is the slope of log error against log dt. Depth references: GJK/EPA "
                        "relative tolerance from 1e-2 to 1e-12 (coarsest to finest).\n\n" +
                        summaryTable(grouped);
  if (!options.outputDirectory.empty()) {
    int plots = 0;
    for (const auto& [reference, methods] : grouped) {
      writeCsv(options.outputDirectory, reference, methods);
      plots += writePlot(options.outputDirectory, reference, methods) ? 1 : 0;
    }
    summary += "\n";
    summary += std::to_string(plots);
    summary += plots ? " work-precision plots written (REFERENCE.png).\n"
                     : " work-precision plots: gnuplot not found or failed; the CSV files hold every figure.\n";
    writeFile(options.outputDirectory / "accuracy.md", summary);
  }
  return summary;
}

}  // namespace physdbg::reports
