// SequentialImpulseSolver::addCandidates: the narrow phase hands over a whole
// pass, so the manifolds (reference-face clipping, ~5% of a box step) are
// built in parallel. Each candidate has its own slot and each piece its own
// scratch; the kept ones are appended in pair order afterwards, so
// manifolds_ is what addCandidate on each in turn gives, for any thread count.
// A manifold the GPU collision stage built arrives prebuilt and is only kept.
#include "engine/parallel/task_system.h"
#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {
namespace {

constexpr std::size_t candidateGrain = 64;  // a manifold is ~0.5 us to build

}  // namespace

int SequentialImpulseSolver::addCandidates(const std::vector<Contact>& candidates, const std::vector<double>& reaches,
                                           const std::vector<RigidBody>& bodies, const StepContext& step,
                                           const std::vector<const ContactManifold*>& prebuilt) {
  candidateManifolds_.resize(candidates.size());
  candidateKept_.resize(candidates.size());
  const auto build = [&](std::size_t begin, std::size_t end) {
    ManifoldScratch scratch;
    for (std::size_t i = begin; i < end; ++i) {
      const Contact& contact = candidates[i];
      candidateKept_[i] = !(contact.result.status == ContactStatus::Separated && contact.result.distance > reaches[i]);
      if (!candidateKept_[i]) continue;
      if (!prebuilt.empty() && prebuilt[i] != nullptr) {
        candidateManifolds_[i] = *prebuilt[i];
        continue;
      }
      ContactManifold& manifold = candidateManifolds_[i] = ContactManifold{};
      manifold.a = contact.a;
      manifold.b = contact.b;
      const RigidBody &a = bodies[contact.a], &b = bodies[contact.b];
      buildManifold(a.collider(), a.transform(), b.collider(), b.transform(), contact.result, reaches[i], scratch,
                    manifold);
    }
  };
  if (step.tasks) step.tasks->parallelFor(candidates.size(), candidateGrain, build);
  else build(0, candidates.size());
  int points = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidateKept_[i]) continue;
    manifolds_.push_back(candidateManifolds_[i]);
    points += candidateManifolds_[i].pointCount;
  }
  return points;
}

}  // namespace physdbg
