#pragma once
// Where a step's time went, stage by stage: wall time on the stepping thread,
// so a stage spread over several threads counts once, and the stages that do
// not gain from threads stand out when one thread count is set beside
// another (stage_timer.h measures them). Nothing in the engine reads these
// back: they never change a result, and they are the only part of StepStats
// that differs from run to run.
#include <array>

namespace physdbg {

struct StepProfile {
  double forces = 0;         // s: gravity, forces, impulses, the solver's step set-up
  double broadPhase = 0;     // fat boxes moved to follow their bodies
  double pairs = 0;          // candidate pairs from the broad phase
  double narrowPhase = 0;    // pairs screened at their bounds, near ones tested
  double manifolds = 0;      // contacts gathered, manifolds built or carried, answers kept
  double solver = 0;         // the contact solver's whole step, bodies moved
  double solverIslands = 0;  // part of `solver`: its islands solved (sequential impulses; the rest
                             // finds loads, islands and substeps)
  double afterSolve = 0;     // kinematic motion, events, history, islands for sleep, sleep
  double total = 0;          // the whole step

  StepProfile& operator+=(const StepProfile& other) {
    forces += other.forces, broadPhase += other.broadPhase, pairs += other.pairs;
    narrowPhase += other.narrowPhase, manifolds += other.manifolds, solver += other.solver;
    solverIslands += other.solverIslands, afterSolve += other.afterSolve, total += other.total;
    return *this;
  }
};

// The stages by name, in step order, for reports (snake_case: JSON keys).
// "other" is what no stage holds: waking touched bodies, the timers themselves.
struct ProfileStage {
  const char* name;
  double seconds;
};
inline std::array<ProfileStage, 10> profileStages(const StepProfile& p) {
  const double staged = p.forces + p.broadPhase + p.pairs + p.narrowPhase + p.manifolds + p.solver + p.afterSolve;
  return {{{"forces", p.forces},
           {"broad_phase", p.broadPhase},
           {"pairs", p.pairs},
           {"narrow_phase", p.narrowPhase},
           {"manifolds", p.manifolds},
           {"solver", p.solver},
           {"solver_islands", p.solverIslands},
           {"after_solve", p.afterSolve},
           {"other", p.total - staged},
           {"total", p.total}}};
}

}  // namespace physdbg
