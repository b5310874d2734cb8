#pragma once
// Benchmarks run by `physdbg bench [NAME]`. Each one prints JSON objects with
// at least name, n, ours_ms, peer, peer_ms and ratio (ours / peer): absolute
// times on shared machines are noise, the ratio measured in one run is not.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "engine/collision_offload.h"
#include "engine/solver/solver_settings.h"

namespace physdbg::bench {

struct BenchOptions {
  bool quick = false;  // smaller sizes, for smoke tests
  // physdbg's contact solver in the scene benchmarks, overriding each scene's
  // (`physdbg bench --solver`); the seed bench then runs only this one.
  std::optional<SolverKind> solver;
  // physdbg's threads in the scene benchmarks (`physdbg bench --threads`, 0
  // every core). Without it they run twice: one thread and every core.
  std::optional<int> threads;
  // The GL context of the gpu benchmark: "osmesa" (llvmpipe) or "egl" (a GPU).
  std::string backend = "osmesa";
  // `physdbg bench --collision gpu`: physdbg's side of the scene benchmarks
  // collides in compute shaders, each world on a stage this makes.
  std::function<std::shared_ptr<CollisionOffload>()> makeGpuCollision;
};


using BenchSink = std::function<void(const nlohmann::json& result)>;

struct Benchmark {
  std::string name;
  std::string description;
  std::function<void(const BenchOptions&, const BenchSink&)> run;
};

// Every benchmark of the project, in a fixed order.
std::vector<Benchmark> allBenchmarks();

// Builds the common fields; `peer` empty and `peerMs` <= 0 mean no peer ran.
nlohmann::json benchRecord(const std::string& name, long long n, double oursMs, const std::string& peer,
                           double peerMs);

}  // namespace physdbg::bench
