#pragma once
// Analytic references for the accuracy report. Each reference builds its
// scene with the given world settings (dt and solver included), runs it and
// returns its error against the closed form.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg::reports {

struct ReferenceResult {
  double error = 0.0;
  std::string note;  // e.g. whether the tumbling box flipped
};

// A scene running in some engine, seen through its bodies (scene order):
// the references that a peer engine can run too measure both through this,
// so each closed form is written once.
class ReferenceSimulation {
 public:
  virtual ~ReferenceSimulation() = default;
  virtual void step() = 0;
  virtual Vec3 position(std::size_t body) const = 0;
  virtual Vec3 linearVelocity(std::size_t body) const = 0;
};
using SimulationFactory = std::function<std::unique_ptr<ReferenceSimulation>(const SceneDescription&)>;

// physdbg's World built from the scene.
std::unique_ptr<ReferenceSimulation> physdbgSimulation(const SceneDescription& scene);

struct TimeStepReference {
  std::string name;
  std::string expectation;  // the closed form, for the summary
  std::function<ReferenceResult(const WorldSettings&)> run;
  // The same measurement in an engine made by the factory (its own solver,
  // the settings' dt and gravity); empty when the reference needs something
  // only physdbg has, and then `peerGap` says what.
  std::function<ReferenceResult(const WorldSettings&, const SimulationFactory&)> runIn;
  std::string peerGap;
};

std::vector<TimeStepReference> timeStepReferences();

struct DepthReference {
  std::string name;
  std::string expectation;
  std::function<ReferenceResult(const NarrowPhaseOptions&)> run;
};

std::vector<DepthReference> depthReferences();

}  // namespace physdbg::reports
