#include "engine/solver/contact_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/baselines/seed_solver.h"
#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {

SubstepContext substepContext(const StepContext& step, int count, double contactHertz, double dampingRatio) {
  SubstepContext substeps;
  substeps.count = count;
  substeps.h = step.dt / count;
  substeps.contactHertz = contactHertz;
  if (contactHertz > 0.0) {
    const double omega = 2.0 * std::numbers::pi * contactHertz;
    const double a1 = 2.0 * dampingRatio + substeps.h * omega;
    const double a2 = substeps.h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    substeps.softness = {omega / a1, a2 * a3, a3};
  }
  return substeps;
}

int flightSubstepCount(const SolverSettings& settings, double dt) {
  const int full = std::max(settings.substeps, 1);
  const int most = std::max(settings.maxSubsteps, full);
  const double wanted = std::ceil(4.0 * settings.contactHertz * dt - 1e-9);
  return static_cast<int>(std::clamp(wanted, static_cast<double>(full), static_cast<double>(most)));
}

int ContactSolver::addCandidates(const std::vector<Contact>& candidates, const std::vector<double>& reaches,
                                 const std::vector<RigidBody>& bodies, const StepContext&,
                                 const std::vector<ManifoldSource>&) {
  int points = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    points += addCandidate(candidates[i], bodies[candidates[i].a], bodies[candidates[i].b], reaches[i]);
  return points;
}

std::unique_ptr<ContactSolver> makeContactSolver(const SolverSettings& settings,
                                                 const NarrowPhaseOptions& narrowPhase) {
  switch (settings.kind) {
    case SolverKind::Seed: return std::make_unique<SeedSolver>(settings, narrowPhase.touchingTolerance);
    case SolverKind::SequentialImpulse: return std::make_unique<SequentialImpulseSolver>(settings);
  }
  return nullptr;
}

}  // namespace physdbg
