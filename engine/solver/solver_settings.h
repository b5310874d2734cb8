#pragma once
// Which contact solver a world uses and how hard it works.
namespace physdbg {

enum class SolverKind {
  Seed,               // the design's one-point response (collision_response.h)
  SequentialImpulse,  // manifolds, friction, warm starting (sequential_impulse_solver.h)
};

struct SolverSettings {
  SolverKind kind = SolverKind::SequentialImpulse;
  int velocityIterations = 10;
  int positionIterations = 4;
  bool warmStarting = true;
  // Penetration left in place so resting contacts stay in contact.
  double linearSlop = 0.005;
  // Share of the remaining penetration removed per position iteration, and the
  // most any one correction may move a point: 25% overlap is undone over a few
  // steps instead of in one explosive push.
  double baumgarte = 0.2;
  double maxCorrection = 0.2;
  // Approach speeds below this (m/s) do not bounce.
  double restitutionThreshold = 0.2;
  // Tangential speeds below this (m/s) use static friction, above it dynamic.
  double stickingSpeed = 0.02;
};

}  // namespace physdbg
