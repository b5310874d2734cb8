// Mass scaling for heavy-on-light contacts (SolverSettings::massRatioLimit).
//
// Gauss-Seidel hands a load down a chain of contacts a fraction light/heavy
// per pass: 10,000 kg on 1 kg would need thousands of passes to hold, and in
// a few the light box is crushed into the floor. Like shock propagation
// (Guendelman et al. 2003), contacts are ordered from the ground up by how
// many contacts separate each body from something immovable (of two as far,
// the lighter is the lower); where an upper
// body is more than the limit times heavier than its lower one, that one
// contact sees the lower body heavier (its inverse mass and inertia scaled
// down), so the load reaches the ground within the passes the solver has.
// The price: in that contact the lower body feels less of what pushes it,
// which is why ordinary mass ratios are left exactly as they are.
#include <algorithm>

#include "engine/solver/sequential_impulse_solver.h"

namespace physdbg {
namespace {

constexpr int unreached = -1;

// Manifold indices by body, compressed: the manifolds of the body of rank k
// are entries[offsets[k] .. offsets[k + 1]).
struct BodyManifolds {
  std::vector<std::uint32_t> offsets, entries;
};

BodyManifolds manifoldsByBody(const std::vector<ContactManifold>& manifolds, const BodyRanks& ranks) {
  BodyManifolds result;
  const std::size_t count = ranks.size();
  result.offsets.assign(count + 1, 0);
  for (const ContactManifold& manifold : manifolds) {
    ++result.offsets[ranks(manifold.a) + 1];
    ++result.offsets[ranks(manifold.b) + 1];
  }
  for (std::size_t k = 0; k < count; ++k) result.offsets[k + 1] += result.offsets[k];
  result.entries.resize(result.offsets[count]);
  std::vector<std::uint32_t> next(result.offsets.begin(), result.offsets.end() - 1);
  for (std::uint32_t m = 0; m < manifolds.size(); ++m) {
    result.entries[next[ranks(manifolds[m].a)]++] = m;
    result.entries[next[ranks(manifolds[m].b)]++] = m;
  }
  return result;
}

}  // namespace

// Levels, breadth first in manifold order (deterministic): 0 for bodies that
// cannot move this step (static, kinematic, asleep), then one more per
// contact. Contacts with no path to the ground are not scaled.
std::vector<std::pair<double, double>> SequentialImpulseSolver::supportMassScales(
    const std::vector<ContactManifold>& manifolds) const {
  std::vector<std::pair<double, double>> scales(manifolds.size(), {1.0, 1.0});
  const double limit = settings_.massRatioLimit;
  if (limit <= 0.0 || manifolds.empty()) return scales;
  const BodyManifolds byBody = manifoldsByBody(manifolds, ranks_);
  RankedTable<int> level;
  level.resize(ranks_);
  std::fill(level.byRank().begin(), level.byRank().end(), unreached);
  std::vector<std::uint32_t> queue;
  for (const ContactManifold& manifold : manifolds)
    for (std::uint32_t id : {manifold.a, manifold.b})
      if (traits_[id].inverseMass == 0.0 && level[id] == unreached) {
        level[id] = 0;
        queue.push_back(id);
      }
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const std::uint32_t lower = queue[next];
    for (std::uint32_t k = byBody.offsets[ranks_(lower)]; k < byBody.offsets[ranks_(lower) + 1]; ++k) {
      const ContactManifold& manifold = manifolds[byBody.entries[k]];
      const std::uint32_t upper = manifold.a == lower ? manifold.b : manifold.a;
      if (level[upper] != unreached) continue;
      level[upper] = level[lower] + 1;
      queue.push_back(upper);
    }
  }
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    const std::uint32_t a = manifolds[m].a, b = manifolds[m].b;
    if (level[a] == unreached || level[b] == unreached) continue;
    // Bodies one contact apart at the same level each lean on the ground
    // through others: a light box a heavy one presses against a wall. The
    // lighter one takes the other's push on to its own supports, so it is
    // the lower one.
    const bool aIsLower = level[a] != level[b] ? level[a] < level[b] : traits_[a].inverseMass > traits_[b].inverseMass;
    const double lowerInverse = traits_[aIsLower ? a : b].inverseMass;
    const double upperInverse = traits_[aIsLower ? b : a].inverseMass;
    if (!(lowerInverse > limit * upperInverse)) continue;  // also skips a fixed lower body
    const double scale = limit * upperInverse / lowerInverse;
    (aIsLower ? scales[m].first : scales[m].second) = scale;
  }
  return scales;
}

}  // namespace physdbg
