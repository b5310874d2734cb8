#include "engine/baselines/static_pairs.h"

#include "engine/narrowphase/narrow_phase.h"
#include "engine/parallel/task_system.h"

namespace physdbg {
namespace {

constexpr std::size_t staticRowGrain = 8;  // a row is up to n overlap tests

StaticPairCounts testStaticRow(const std::vector<RigidBody>& bodies, const std::vector<bool>& present,
                               std::size_t i, const NarrowPhaseOptions& options) {
  StaticPairCounts counts;
  if (!bodies[i].isStatic() || !present[i]) return counts;
  const Aabb boxI = bodies[i].collider().worldBounds(bodies[i].transform());
  for (std::size_t j = i + 1; j < bodies.size(); ++j) {
    if (!bodies[j].isStatic() || !present[j]) continue;
    ++counts.tested;
    if (!boxI.overlaps(bodies[j].collider().worldBounds(bodies[j].transform()))) continue;
    counts.narrowPhase.add(
        collide(bodies[i].collider(), bodies[i].transform(), bodies[j].collider(), bodies[j].transform(), options));
  }
  return counts;
}

}  // namespace

StaticPairCounts testStaticPairs(const std::vector<RigidBody>& bodies, const std::vector<bool>& present,
                                 const TaskSystem& tasks, const NarrowPhaseOptions& options) {
  std::vector<StaticPairCounts> rows(bodies.size());
  tasks.parallelFor(bodies.size(), staticRowGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) rows[i] = testStaticRow(bodies, present, i, options);
  });
  StaticPairCounts total;
  for (const StaticPairCounts& row : rows) {
    total.tested += row.tested;
    total.narrowPhase.pairs += row.narrowPhase.pairs;
    total.narrowPhase.fastPath += row.narrowPhase.fastPath;
    total.narrowPhase.gjk += row.narrowPhase.gjk;
    total.narrowPhase.epa += row.narrowPhase.epa;
  }
  return total;
}

}  // namespace physdbg
