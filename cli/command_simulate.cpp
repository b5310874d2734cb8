// physdbg simulate: runs a scene without rendering; summary, CSV trace,
// state hash, contact events.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>

#include "cli/arguments.h"
#include "cli/collision_device.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/csv_output.h"
#include "cli/limits.h"
#include "cli/numerical_faults.h"
#include "cli/output_folder.h"
#include "cli/state_hash.h"
#include "cli/step_series.h"
#include "gpu/gpu_collision.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

// One row per body per step. Full precision (%.17g) so a trace can be
// compared bit for bit (`physdbg diff`).
class TraceWriter {
 public:
  explicit TraceWriter(const std::string& path)
      : output_("--trace", path, "step,time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz") {}

  void write(const World& world) {
    char line[512];
    for (std::size_t i = 0; i < world.bodyCount(); ++i) {
      if (!world.isPresent(static_cast<BodyId>(i))) continue;  // added later in the run, or removed
      const RigidBody& body = world.body(static_cast<BodyId>(i));
      const Vec3& p = body.position();
      const Quat& q = body.orientation();
      const Vec3& v = body.linearVelocity();
      const Vec3& w = body.angularVelocity();
      std::snprintf(line, sizeof line,
                    "%d,%.17g,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                    world.stepCount(), world.time(), i, p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z(), v.x(),
                    v.y(), v.z(), w.x(), w.y(), w.z());
      output_.writeLine(line);
    }
    output_.check();
  }

  void close() { output_.close(); }

 private:
  CsvOutput output_;
};

// Prints contact events as they happen: "step 12 begin 0 3".
class EventPrinter final : public ContactListener {
 public:
  explicit EventPrinter(const World& world) : world_(world) {}
  void onContactBegin(const Contact& contact) override { print("begin", contact.a, contact.b); }
  void onContactStay(const Contact& contact) override { print("stay", contact.a, contact.b); }
  void onContactEnd(std::uint32_t a, std::uint32_t b) override { print("end", a, b); }

 private:
  void print(const char* what, std::uint32_t a, std::uint32_t b) {
    std::printf("step %d %s %u %u\n", world_.stepCount() + 1, what, a, b);
  }
  const World& world_;
};

// "step 120 hash 0123456789abcdef": the same hash as --hash, so the last
// line of --hash-every equals --hash.
void printStepHash(const World& world) {
  std::printf("step %d hash %s\n", world.stepCount(), hexHash(worldStateHash(world)).c_str());
}

// Mean ms per step in each stage (step_profile.h), in step order.
void printStages(const StepProfile& profile, int steps) {
  std::printf("stages (mean ms per step):");
  const char* separator = " ";
  for (const ProfileStage& stage : profileStages(profile)) {
    if (std::string_view(stage.name) == "total") continue;
    std::string name = stage.name;
    std::replace(name.begin(), name.end(), '_', ' ');
    std::printf("%s%s %.4f", separator, name.c_str(), 1e3 * stage.seconds / std::max(steps, 1));
    separator = ", ";
  }
  std::printf("\n");
}

}  // namespace

int runSimulate(const std::vector<std::string>& args) {
  CommandSpec spec{
      "simulate",
      "SCENE [--steps N] [--trace FILE.csv] [--series FILE.csv] [--hash] [--hash-every N] [--events]",
      "Runs SCENE (a built-in name or a scene file) without rendering and prints a summary.\n"
      "Exits with 1 when a body's state became NaN or Inf (the body is reported and frozen).",
      {{"--trace", "", "FILE.csv", "write every body's state at every step (step 0 = initial state)"},
       {"--series", "", "FILE.csv",
        "write whole-world figures per step: energies, momenta, contacts, penetration, awake, substeps, step time"},
       {"--hash", "", "", "print a hash of all body states at the end (determinism checks)"},
       {"--hash-every", "", "N", "print 'step S hash H' every N steps (and after the last): where two runs part"},
       {"--events", "", "", "print contact events: 'step N begin|stay|end A B'"}},
      1,
      1};
  addOptions(spec, {OptionGroup::RunSteps, OptionGroup::Solver, OptionGroup::Threads, OptionGroup::Collision,
                    OptionGroup::Backend});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  const int steps = readSteps(*parsed, scene.steps);
  const std::shared_ptr<CollisionOffload> offload = collisionOffloadFor(scene, readBackend(*parsed));
  World world = buildWorld(scene, offload);
  EventPrinter events(world);
  if (parsed->has("--events")) world.setContactListener(&events);
  std::optional<TraceWriter> trace;
  if (parsed->has("--trace")) {
    trace.emplace(parsed->value("--trace"));
    trace->write(world);
  }
  std::optional<SeriesWriter> series;
  if (parsed->has("--series")) {
    series.emplace(parsed->value("--series"));
    series->write(measureSeries(world, 0.0));
  }
  const int hashEvery = parsed->has("--hash-every")
                            ? parsed->positiveInt("--hash-every", 1, static_cast<int>(limits::maxSteps))
                            : 0;

  double stepSeconds = 0;
  StepProfile profile;
  for (int step = 0; step < steps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    world.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stepSeconds += seconds;
    profile += world.lastStepStats().profile;
    if (trace) trace->write(world);
    if (series) series->write(measureSeries(world, 1e3 * seconds));
    if (hashEvery > 0 && (world.stepCount() % hashEvery == 0 || step + 1 == steps)) printStepHash(world);
  }
  if (trace) trace->close();
  if (series) series->close();

  double kineticEnergy = 0;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    if (!world.isFrozen(static_cast<BodyId>(i)) && world.isPresent(static_cast<BodyId>(i))) kineticEnergy += world.body(static_cast<BodyId>(i)).kineticEnergy();
  }
  std::printf("scene %s: %zu bodies, %d steps of %.6g s (%.4g s simulated)\n", scene.name.c_str(), world.bodyCount(),
              steps, scene.world.dt, world.time());
  std::printf("step time %.4f ms (mean) on %d thread%s, final kinetic energy %.6g J\n", 1e3 * stepSeconds / steps,
              world.threadCount(), world.threadCount() == 1 ? "" : "s", kineticEnergy);
  printStages(profile, steps);
  const StepStats& stats = world.lastStepStats();
  std::printf(
      "last step: %d awake (%d with axis locks), %d sleeping, %d candidate pairs, %d contacts, %d manifold "
      "points, largest penetration %.4g m; narrow phase: %lld fast path, %lld box-box, %lld GJK, %lld EPA, "
      "%lld taken again\n",
      stats.awakeBodies, stats.lockedBodies, stats.sleepingBodies, stats.candidatePairs, stats.contacts,
      stats.manifoldPoints, stats.largestPenetration, stats.narrowPhase.fastPath, stats.narrowPhase.boxBox,
      stats.narrowPhase.gjk, stats.narrowPhase.epa, stats.narrowPhase.reused);
  if (stats.filteredPairs > 0)
    std::printf("filters: %d pairs kept apart before the narrow phase\n", stats.filteredPairs);
  if (stats.narrowPhase.meshTriangles > 0)
    std::printf("meshes: %lld triangles tested, %lld contacts on inactive edges given the face normal\n",
                stats.narrowPhase.meshTriangles, stats.narrowPhase.meshCorrected);
  if (stats.substeps > 0)
    std::printf("solver: %d substeps, contacts at %.4g Hz\n", stats.substeps, stats.contactHertz);
  if (const auto* gpu = dynamic_cast<const gpu::GpuCollision*>(offload.get())) {
    const gpu::GpuCollisionTimings timings = gpu->timings();
    std::printf("collision on the gpu (%s): %lld pairs tested there in %lld dispatches; upload %.4f, dispatch %.4f, "
                "readback %.4f ms per step\n",
                gpu->identity().renderer.c_str(), timings.pairsTested, timings.dispatches,
                1e3 * timings.uploadSeconds / steps, 1e3 * timings.dispatchSeconds / steps,
                1e3 * timings.readbackSeconds / steps);
  }
  if (parsed->has("--hash")) std::printf("state hash %s\n", hexHash(worldStateHash(world)).c_str());
  return reportNumericalFaults("simulate", world);
}

}  // namespace physdbg::cli
