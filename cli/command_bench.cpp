#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/repeats.h"
#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/number_option.h"
#include "gpu/gpu_collision.h"

namespace physdbg::cli {
namespace {

std::string formatNumber(const nlohmann::json& value) {
  if (value.is_null()) return "-";
  char text[32];
  if (value.is_number_integer()) std::snprintf(text, sizeof text, "%lld", value.get<long long>());
  else if (value.is_number()) std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  else return value.is_string() ? value.get<std::string>() : value.dump();
  return text;
}

void printRow(const nlohmann::json& record) {
  // With --repeat, the spread of the runs' ratios follows the median.
  const nlohmann::json none;
  const std::string range =
      record.value("ratio_min", none).is_number()
          ? "  (" + formatNumber(record["ratio_min"]) + "-" + formatNumber(record["ratio_max"]) + ")"
          : "";
  // A row whose engines ended in different states compares different work.
  const bool differentWork = record.value("same_work", none).is_boolean() && !record["same_work"].get<bool>();
  // The memory benchmark's ratio compares peak memory, not time.
  const std::string ratioOf = record.value("ratio_of", none).is_string()
                                  ? "  (ratio of " + record["ratio_of"].get<std::string>() + ")"
                                  : "";
  std::printf("%-34s %8s %7s %12s %-22s %12s %8s%s%s%s\n", formatNumber(record["name"]).c_str(),
              formatNumber(record["n"]).c_str(), formatNumber(record.value("threads", none)).c_str(),
              formatNumber(record["ours_ms"]).c_str(), formatNumber(record["peer"]).c_str(),
              formatNumber(record["peer_ms"]).c_str(), formatNumber(record["ratio"]).c_str(), range.c_str(),
              ratioOf.c_str(),
              differentWork ? "  NOT THE SAME WORK (same_work false)" : "");
  std::fflush(stdout);
}

void emit(const nlohmann::json& record, bool json) {
  if (json)
    std::cout << record.dump() << std::endl;
  else
    printRow(record);
}

}  // namespace

int runBench(const std::vector<std::string>& args) {
  std::string names;
  for (const auto& benchmark : bench::allBenchmarks()) names += "\n  " + benchmark.name + ": " + benchmark.description;
  const CommandSpec spec{
      "bench",
      "[NAME] [--json] [--quick] [--repeat N] [--solver seed|sequential_impulse] [--threads N] [--collision cpu|gpu] "
      "[--backend B]",
      "Runs the benchmark NAME, or all of them, each side by side with its peer engine in the same "
      "run.\nratio = ours / peer: below 1 means physdbg is faster. Benchmarks:" +
          names,
      {{"--json", "", "", "print one JSON object per line instead of a table"},
       {"--quick", "", "", "small sizes (a smoke test, not a measurement)"},
       {"--repeat", "", "N",
        "run everything N times (1-20, default 1), each run side by side with the peer, and print "
        "per case the run with the median ratio, with every run's ratio (ratio_runs) and their "
        "range"},
       {"--solver", "", "seed|sequential_impulse",
        "physdbg's contact solver in the scene benchmarks (drop, pyramid, jolt_pyramid, sleeping; seed runs only it)"},
       {"--threads", "", "N",
        "physdbg's threads in the scene benchmarks (drop, pyramid, jolt_pyramid, sleeping) and tree "
        "\"moving\": N alone (0 every core); by default one row on 1 thread and one on every core, each "
        "with its ratio to Bullet"},
       {"--collision", "", "cpu|gpu",
        "where physdbg's collision detection runs in the scene benchmarks (drop, pyramid, jolt_pyramid, "
        "sleeping): cpu (default) or compute shaders on the --backend context"},
       {"--backend", "", "osmesa|egl",
        "GL context of the gpu benchmark: OSMesa's llvmpipe (default) or EGL, which reaches a GPU"}},
      0,
      1};
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const std::string wanted = parsed->positional().empty() ? "" : parsed->positional()[0];
  std::vector<bench::Benchmark> selected;
  for (const auto& benchmark : bench::allBenchmarks()) {
    if (wanted.empty() || benchmark.name == wanted) selected.push_back(benchmark);
  }
  if (selected.empty()) throw UsageError("unknown benchmark '" + wanted + "'; available:" + names);
  const bool json = parsed->has("--json");
  const int repeats = numberOption(*parsed, "--repeat", 1, 1, 20);
  if (!json)
    printRow({{"name", "name"}, {"n", "n"}, {"threads", "threads"}, {"ours_ms", "ours_ms"}, {"peer", "peer"},
              {"peer_ms", "peer_ms"}, {"ratio", "ratio"}});
  bench::BenchOptions options;
  options.quick = parsed->has("--quick");
  options.solver = readSolverKind(*parsed);
  options.threads = readThreads(*parsed);
  options.backend = parsed->has("--backend") ? parsed->value("--backend") : "osmesa";
  const render::Backend backend = render::parseBackend(options.backend);  // a bad name fails before any run
  if (readCollisionDevice(*parsed) == CollisionDevice::Gpu)
    options.makeGpuCollision = [backend] { return std::make_shared<gpu::GpuCollision>(backend); };
  std::vector<std::vector<nlohmann::json>> runs(repeats);
  for (int run = 0; run < repeats; ++run) {
    if (repeats > 1) std::cerr << "bench: run " << run + 1 << " of " << repeats << std::endl;
    for (const auto& benchmark : selected) {
      try {
        benchmark.run(options, [&](const nlohmann::json& record) {
          if (repeats == 1)
            emit(record, json);
          else
            runs[run].push_back(record);
        });
      } catch (const gpu::ComputeUnavailable& error) {
        throw UsageError("bench " + benchmark.name + ": " + error.what());
      }
    }
  }
  if (repeats > 1)
    for (const nlohmann::json& record : bench::medianOfRuns(runs)) emit(record, json);
  return 0;
}

}  // namespace physdbg::cli
