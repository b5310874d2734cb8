// Files and summary of the accuracy report. Plots are drawn by the caller's
// plot function (the physdbg command's one plotter), never by an outside
// program: the report is the same on every machine.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "reports/accuracy_report.h"
#include "reports/html_index.h"

namespace physdbg::reports {
namespace {

using Grouped = std::map<std::string, AccuracyMethods>;

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
              const AccuracyMethods& methods) {
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

std::string summaryTable(const Grouped& grouped) {
  std::string text =
      "| reference | method | fitted order | error (coarsest) | error (finest) | ms (finest) | note (finest) |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& [reference, methods] : grouped) {
    for (const auto& [method, samples] : methods) {
      const AccuracySample &coarsest = samples.front(), &finest = samples.back();
      const std::string order = isTimeStep(reference) ? fitOrder(samples).text : "n/a (a tolerance sweep)";
      text += "| " + reference + " | " + method + " | " + order + " | " + number(coarsest.error) + " | " +
              number(finest.error) + " | " + number(finest.milliseconds) + " | " + finest.note + " |\n";
    }
  }
  return text;
}

// Which references the peer ran, and why the others could not be.
std::string peerText(const AccuracyOptions& options) {
  if (!options.peer) return "\n" + options.peerName + ": not built (PHYSDBG_WITH_PEERS off or Bullet not found), so no peer series.\n";
  std::string text = "\n" + options.peerName + " (its default sequential-impulse solver, 10 iterations, one substep per "
                     "step, same scene and dt) runs as one more method where the reference can be expressed in it:\n\n";
  for (const TimeStepReference& reference : timeStepReferences()) {
    text += "- " + reference.name + ": " + (reference.runIn ? std::string("run") : reference.peerGap) + "\n";
  }
  return text + "- depth_*: not run in the peer: the sweep is over physdbg's own GJK/EPA tolerances\n";
}

std::vector<AccuracySample> allSamples(const AccuracyOptions& options,
                                       const std::function<void(const std::string&)>& progress) {
  std::vector<AccuracySample> samples = runAccuracySweep(options.quick, progress);
  if (!options.peer) return samples;
  if (progress) progress("accuracy: " + options.peerName);
  const auto peer = runPeerAccuracySweep(options.quick, options.peer, options.peerName);
  samples.insert(samples.end(), peer.begin(), peer.end());
  return samples;
}

}  // namespace

std::string runAccuracyReport(const AccuracyOptions& options, const std::function<void(const std::string&)>& progress) {
  const Grouped grouped = group(allSamples(options, progress));
  std::string summary = "# Accuracy\n\nTime-step references: dt from 1/30 s to 1/" +
                        std::string(options.quick ? "240" : "3840") +
                        " s; the order is the slope of log error against log dt, given only where errors fall steadily with dt "
                        "(otherwise the table says why; \"exact\" means round-off at every dt). Depth references: GJK/EPA "
                        "relative tolerance from 1e-2 to 1e-12 (coarsest to finest).\n\n" +
                        summaryTable(grouped) + peerText(options);
  if (!options.outputDirectory.empty()) {
    std::vector<std::string> plots;
    for (const auto& [reference, methods] : grouped) {
      writeCsv(options.outputDirectory, reference, methods);
      if (!options.plot) continue;
      options.plot(options.outputDirectory / (reference + ".png"), reference, methods);
      plots.push_back(reference + ".png");
    }
    summary += "\n" + std::to_string(plots.size()) +
               " work-precision plots written (REFERENCE.png), CSV files beside them.\n";
    writeFile(options.outputDirectory / "accuracy.md", summary);
    writeHtmlIndex(options.outputDirectory, "physdbg accuracy", summary, plots);
  }
  return summary;
}

}  // namespace physdbg::reports
