#pragma once
// The world owns the bodies and advances them. World::step() is the one place
// that shows the order of a step; each stage lives in its own file.
#include <cstdint>
#include <string>
#include <vector>

#include "debugdraw/primitives.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/math.h"

namespace physdbg {

using BodyId = std::uint32_t;

struct WorldSettings {
  Vec3 gravity{0.0, -9.81, 0.0};
  double dt = 1.0 / 60.0;
};

// A body whose state stopped being finite: reported once, then frozen.
struct NumericalFault {
  BodyId body = 0;
  int step = 0;
  std::string what;
};

// Work done by the last step, for reports and overlays: counters, not claims.
struct StepStats {
  int awakeBodies = 0;
  int integratedBodies = 0;
};

class World {
 public:
  explicit World(const WorldSettings& settings = {});

  // Throws std::invalid_argument (see RigidBody) for a bad definition.
  BodyId addBody(const BodyDefinition& definition);

  std::size_t bodyCount() const { return bodies_.size(); }
  RigidBody& body(BodyId id) { return bodies_.at(id); }
  const RigidBody& body(BodyId id) const { return bodies_.at(id); }
  const std::vector<RigidBody>& bodies() const { return bodies_; }

  const WorldSettings& settings() const { return settings_; }
  int stepCount() const { return stepCount_; }
  double time() const { return stepCount_ * settings_.dt; }

  void step();

  bool isFrozen(BodyId id) const { return frozen_.at(id); }
  const std::vector<NumericalFault>& numericalFaults() const { return faults_; }
  const StepStats& lastStepStats() const { return stats_; }

  // Appends the primitives of the requested layers; computes nothing for the
  // layers that are not requested.
  void emitDebugDraw(debugdraw::LayerSet layers, debugdraw::Frame& frame) const;

 private:
  void integrateVelocities();
  void integratePositions();
  void freezeNonFiniteBodies();

  WorldSettings settings_;
  std::vector<RigidBody> bodies_;
  std::vector<bool> frozen_;
  std::vector<NumericalFault> faults_;
  StepStats stats_;
  int stepCount_ = 0;
};

}  // namespace physdbg
