#pragma once
// The compute shaders of GpuBroadPhase. Shared by them: binding 0 holds the
// boxes (two vec4 per proxy slot, the role in the min's w: 0 no proxy, 1 a
// proxy that cannot drive a pair, 2 a dynamic awake one), binding 1 the sort
// entries (uvec2: order-preserving key of the box's min on the sweep axis,
// slot), binding 2 the pair list (a count, a pad word, then uvec2 pairs),
// binding 3 the live boxes in sort order.
#include <cstdint>

namespace physdbg::gpu {

// Threads per work group of every broad-phase shader; the local sort holds
// twice as many entries in shared memory.
inline constexpr std::uint32_t broadPhaseGroupSize = 256;
inline constexpr std::uint32_t broadPhaseSortBlock = 2 * broadPhaseGroupSize;

// Writes one sort entry per slot up to paddedCount; slots without a proxy
// (and the padding) get the largest key, so they sort last.
extern const char* const broadPhaseKeyShader;
// Bitonic sort within one block of broadPhaseSortBlock entries in shared
// memory: every stage when mergeStage is 0, else the steps of stage
// mergeStage that stay within a block.
extern const char* const broadPhaseLocalSortShader;
// One bitonic step (stage, step) whose partners lie in different blocks.
extern const char* const broadPhaseGlobalStepShader;
// Copies the live boxes into sort order (binding 3), each with its slot in
// the max's w: the sweep then reads neighbours from adjacent memory.
extern const char* const broadPhaseGatherShader;
// From every sorted box, walks the entries after it while their min on the
// sweep axis is within its max, and appends the overlapping eligible pairs.
extern const char* const broadPhaseSweepShader;

}  // namespace physdbg::gpu
