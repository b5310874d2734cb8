#pragma once
// The design's baseline without static-pair skipping (WorldSettings::
// skipStaticPairs off): pairs of bodies that cannot move still cost an
// overlap test and, when their boxes overlap, a narrow-phase test whose
// answer nobody uses. Kept to measure what skipping saves; out of the step's
// hot path, run only when asked for.
#include <vector>

#include "engine/dynamics/rigid_body.h"
#include "engine/narrowphase/narrow_phase_options.h"

namespace physdbg {

class TaskSystem;

struct StaticPairCounts {
  int tested = 0;
  NarrowPhaseCounters narrowPhase;  // pairs, fastPath, gjk and epa
};

// Every pair of present static bodies. Rows (the lower body of each pair)
// run in parallel; their counts are summed after, in row order.
StaticPairCounts testStaticPairs(const std::vector<RigidBody>& bodies, const std::vector<bool>& present,
                                 const TaskSystem& tasks, const NarrowPhaseOptions& options);

}  // namespace physdbg
