// SequentialImpulseSolver::addCandidates: the narrow phase hands over a whole
// pass, so the manifolds (reference-face clipping, ~5% of a box step) are
// built in parallel. Each kept candidate has its own slot in manifolds_, in
// pair order, and each piece its own scratch, so manifolds_ is what
// addCandidate on each in turn gives, for any thread count.
// A manifold the GPU collision stage built arrives prebuilt and is only
// copied; a kept answer is carried to today's poses straight into its slot.
#include "engine/contacts/contact_reuse.h"
#include "engine/parallel/task_system.h"
#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {
namespace {

constexpr std::size_t candidateGrain = 64;  // a manifold is ~0.5 us to build
constexpr std::size_t notKept = ~std::size_t{0};

}  // namespace

int SequentialImpulseSolver::addCandidates(const std::vector<Contact>& candidates, const std::vector<double>& reaches,
                                           const std::vector<RigidBody>& bodies, const StepContext& step,
                                           const std::vector<ManifoldSource>& sources) {
  // Which candidates are kept, and where each goes: decided first, so the
  // manifolds are built straight into manifolds_ in parallel (building them
  // aside and appending was a serial copy of every manifold, 600 bytes each).
  const std::size_t first = manifolds_.size();
  // A whole pass takes the spare manifolds: every slot below is assigned in
  // full, so what they held does not matter, and only slots past them are
  // constructed.
  if (first == 0) std::swap(manifolds_, spareManifolds_);
  candidateSlot_.resize(candidates.size());
  std::size_t kept = first;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const ContactResult& result = candidates[i].result;
    const bool keep = !(result.status == ContactStatus::Separated && result.distance > reaches[i]);
    candidateSlot_[i] = keep ? kept++ : notKept;
  }
  manifolds_.resize(kept);
  const auto build = [&](std::size_t begin, std::size_t end) {
    ManifoldScratch scratch;
    for (std::size_t i = begin; i < end; ++i) {
      if (candidateSlot_[i] == notKept) continue;
      ContactManifold& manifold = manifolds_[candidateSlot_[i]];
      const ManifoldSource source = sources.empty() ? ManifoldSource{} : sources[i];
      if (source.built != nullptr) {
        manifold = *source.built;
        continue;
      }
      if (source.kept != nullptr) {
        const ReusableContact& kept = *source.kept;
        carryManifold(kept, bodies[kept.pair.a].transform(), bodies[kept.pair.b].transform(), manifold);
        continue;
      }
      const Contact& contact = candidates[i];
      manifold = ContactManifold{};
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
  for (std::size_t m = first; m < manifolds_.size(); ++m) points += manifolds_[m].pointCount;
  return points;
}

}  // namespace physdbg
