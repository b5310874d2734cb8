#pragma once
// The compute shaders of GpuBroadPhase, a linear BVH rebuilt every call:
// Morton codes, a bitonic sort, Karras's parallel build, bounds, and one
// traversal per leaf. Bindings shared by them: 0 the boxes by slot (two vec4,
// the role in the min's w: 0 no proxy, 1 a proxy that cannot drive a pair, 2
// a dynamic awake one); 1 the sort entries (uvec2: Morton code, slot); 2 the
// pair list (a count, a pad word, then uvec2 pairs of slots); 3 the live
// boxes in sort order (the leaves); 4 the internal nodes' links (uvec4: left
// and right child, a leaf's position flagged by the high bit, then the first
// and last leaf below); 5 the internal nodes' boxes (the min's w: the highest
// role below).
#include <cstdint>
#include <string>

namespace physdbg::gpu {

// Threads per work group of every broad-phase shader; the local sort holds
// twice as many entries in shared memory.
inline constexpr std::uint32_t broadPhaseGroupSize = 256;
inline constexpr std::uint32_t broadPhaseSortBlock = 2 * broadPhaseGroupSize;

// A shader's whole source: the shared version, group size, bindings and
// helpers, then one of the bodies below.
std::string broadPhaseProgramSource(const char* body);

// Writes one sort entry per slot up to paddedCount, the code of the box
// centre in the uniform grid origin + cell / scale; slots without a proxy
// (and the padding) get a key above every code, so they sort last.
extern const char* const broadPhaseKeyShader;
// Bitonic sort within one block of broadPhaseSortBlock entries in shared
// memory: every stage when mergeStage is 0, else the steps of stage
// mergeStage that stay within a block. Ties on the code go by slot.
extern const char* const broadPhaseLocalSortShader;
// One bitonic step (stage, step) whose partners lie in different blocks.
extern const char* const broadPhaseGlobalStepShader;
// Copies the live boxes into sort order: the leaves.
extern const char* const broadPhaseGatherShader;
// Karras (2012): each internal node finds its leaf range and split from the
// sorted codes alone, all nodes at once; internal node 0 is the root.
extern const char* const broadPhaseBuildShader;
// Each internal node's box as the union of its leaf range: more reads than a
// bottom-up refit (the ranges nest, ~n log n in all), but no atomics or
// ordering between threads.
extern const char* const broadPhaseBoundsShader;
// Each leaf walks the tree for overlapping leaves after it in sort order
// (so every pair is found once), skipping subtrees whose leaves all lie
// before it or none of which could make an eligible pair with it.
extern const char* const broadPhaseTraverseShader;

}  // namespace physdbg::gpu
