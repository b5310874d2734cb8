#pragma once
// What every stage of one step shares, computed once by World::step and
// passed down: the step length, gravity and the world's threads. A solver that cuts the step into
// substeps derives its SubstepContext from it once per island.
#include "engine/math.h"

namespace physdbg {

class TaskSystem;

struct StepContext {
  double dt = 1.0 / 60.0;  // s
  Vec3 gravity = Vec3::Zero();
  // The world's threads; null runs everything on the caller's thread. Work
  // spread over them must give the same result for any count (task_system.h).
  const TaskSystem* tasks = nullptr;
};

// A soft contact's coefficients at one substep length (Box2D v3's "soft
// step"): the bias rate that pushes overlap out, and how much of the rigid
// mass and of the accumulated impulse one iteration uses.
struct Softness {
  double biasRate = 0.0, massScale = 1.0, impulseScale = 0.0;
};

// One island's (or the free bodies') substeps: how many, their length h, and
// the contact frequency and softness the solver uses at that h.
struct SubstepContext {
  int count = 1;
  double h = 0.0;  // s: dt / count
  double contactHertz = 0.0;
  Softness softness;  // rigid (the default) when contactHertz is 0
};

SubstepContext substepContext(const StepContext& step, int count, double contactHertz, double dampingRatio);

}  // namespace physdbg
