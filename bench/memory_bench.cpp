// "memory": what a scene holds in memory, physdbg beside Bullet in the same
// run. The figure is the peak resident set above the process's floor, as the
// operating system counts it (pages touched, allocator slack and freed-but-
// kept blocks included), not what the allocator says is in use.
//
// Each engine runs each case in a child process of its own (memory_probe.h).
// physdbg runs on one thread, so the child starts no threads.
//
// Cases, all from the drop scene (drop_scene.h, jittered, sleeping off):
// - memory/boxes_at_rest: N boxes dropped and settled, 600 steps;
// - memory/spheres_apart: N spheres without gravity, never touching (the
//   bodies' own share, 60 steps);
// - memory/spheres_pile: N spheres dropped into a collapsed pile, 600 steps.
// Per contact = (pile - apart) / the pile's contacts: what its contacts hold
// beyond the bodies; bytes_per_contact_total divides the whole pile instead.
#include <nlohmann/json.hpp>
#include <string>

#include "bench/bench.h"
#include "bench/drop_scene.h"
#include "bench/memory_probe.h"
#include "bench/side_by_side.h"

namespace physdbg::bench {
namespace {

// Goals of issue 46: 1.5 KB a body at rest, 0.5 KB a contact in a pile.
constexpr double kGoalBytesPerBody = 1536.0;
constexpr double kGoalBytesPerContact = 512.0;

nlohmann::json describe(const EngineRun& run) {
  nlohmann::json result;
  result["ms"] = run.msPerStep;
  result["contacts"] = run.contacts;
  result["kinetic_energy"] = run.kineticEnergy;
  result["ran"] = run.ran;
  std::vector<double> positions;
  for (const Vec3& p : run.finalPositions) positions.insert(positions.end(), {p.x(), p.y(), p.z()});
  result["final_positions"] = positions;
  return result;
}

EngineRun runFrom(const nlohmann::json& result) {
  EngineRun run;
  run.ran = result["ran"].get<bool>();
  run.msPerStep = result["ms"].get<double>();
  run.contacts = result["contacts"].get<int>();
  run.kineticEnergy = result["kinetic_energy"].get<double>();
  const std::vector<double> positions = result["final_positions"].get<std::vector<double>>();
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
    run.finalPositions.emplace_back(positions[i], positions[i + 1], positions[i + 2]);
  return run;
}

struct MemoryCase {
  std::string name;
  DropShape shape = DropShape::Box;
  bool gravity = true;
  int steps = 600;
};

struct CaseResult {
  nlohmann::json record;
  double oursBytes = 0.0, peerBytes = 0.0;
  bool peerRan = false;
};

CaseResult runCase(const MemoryCase& memoryCase, int count, const BenchOptions& options) {
  DropScene drop = dropScene(count, memoryCase.shape);
  if (!memoryCase.gravity) drop.scene.world.gravity = Vec3::Zero();
  const int steps = options.quick ? 20 : memoryCase.steps;
  const nlohmann::json ours = measureInChild(memoryCase.name + " in physdbg", [&] {
    return describe(runOurs(drop.scene, steps, options, 1));
  });
  const nlohmann::json peer = measureInChild(memoryCase.name + " in Bullet", [&] {
    return describe(runBullet(drop.scene, steps, false));
  });
  CaseResult result;
  result.oursBytes = ours["peak_bytes"].get<double>();
  result.peerBytes = peer["peak_bytes"].get<double>();
  result.peerRan = peer["ran"].get<bool>();
  nlohmann::json& record = result.record;
  record = benchRecord(memoryCase.name, count, ours["ms"].get<double>(),
                       result.peerRan ? "bullet 3.24 btDbvt+SI(10)" : "", peer["ms"].get<double>());
  // This benchmark's ratio compares memory; ours_ms and peer_ms are the measured runs' step times.
  record["ratio"] = result.peerRan ? nlohmann::json(result.oursBytes / result.peerBytes) : nlohmann::json();
  record["ratio_of"] = "peak_rss_above_floor";
  record["threads"] = 1;
  record["steps"] = steps;
  record["ours_peak_bytes"] = result.oursBytes;
  record["ours_floor_bytes"] = ours["floor_bytes"];
  record["ours_bytes_per_body"] = result.oursBytes / count;
  if (result.peerRan) {
    record["peer_peak_bytes"] = result.peerBytes;
    record["peer_floor_bytes"] = peer["floor_bytes"];
    record["peer_bytes_per_body"] = result.peerBytes / count;
  }
  WorkCheck check;
  check.firstDynamic = static_cast<std::size_t>(drop.firstDropped);
  check.outside = [&drop](const Vec3& position) { return leftContainer(position, drop.container); };
  addWorkFields(record, runFrom(ours), runFrom(peer), check);
  return result;
}

// What each contact of the pile holds beyond its bodies (`apart`: the same
// bodies, never touching).
void addContactFields(nlohmann::json& pile, const CaseResult& pileResult, const CaseResult& apart) {
  const auto perContact = [&](const std::string& prefix, double pileBytes, double apartBytes) {
    const int contacts = pile[prefix + "_contacts"].get<int>();
    if (contacts <= 0) return;
    pile[prefix + "_bytes_per_contact"] = (pileBytes - apartBytes) / contacts;
    pile[prefix + "_bytes_per_contact_total"] = pileBytes / contacts;
  };
  perContact("ours", pileResult.oursBytes, apart.oursBytes);
  if (pileResult.peerRan) perContact("peer", pileResult.peerBytes, apart.peerBytes);
  pile["goal_bytes_per_contact"] = kGoalBytesPerContact;
  pile["meets_goal"] = pile.contains("ours_bytes_per_contact") &&
                       pile["ours_bytes_per_contact"].get<double>() <= kGoalBytesPerContact;
}

void runMemoryBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int count = options.quick ? 500 : 16000;
  CaseResult boxes = runCase({"memory/boxes_at_rest", DropShape::Box, true, 600}, count, options);
  boxes.record["goal_bytes_per_body"] = kGoalBytesPerBody;
  boxes.record["meets_goal"] = boxes.record["ours_bytes_per_body"].get<double>() <= kGoalBytesPerBody;
  sink(boxes.record);
  const CaseResult apart = runCase({"memory/spheres_apart", DropShape::Sphere, false, 60}, count, options);
  sink(apart.record);
  CaseResult pile = runCase({"memory/spheres_pile", DropShape::Sphere, true, 600}, count, options);
  addContactFields(pile.record, pile, apart);
  sink(pile.record);
}

}  // namespace

Benchmark memoryBenchmark() {
  return {"memory",
          "peak resident memory above the process floor, physdbg and Bullet each in a child process: 16,000 "
          "boxes at rest, 16,000 spheres apart and in a collapsed pile (per body, per contact)",
          runMemoryBenchmark};
}

}  // namespace physdbg::bench
