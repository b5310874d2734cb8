#include "gpu/broad_phase_shaders.h"

namespace physdbg::gpu {

// The group size and block are spelled out in the sources; the static_asserts
// below keep them equal to the constants the dispatches use.
static_assert(broadPhaseGroupSize == 256 && broadPhaseSortBlock == 512);

const char* const broadPhaseKeyShader = R"glsl(#version 430
layout(local_size_x = 256) in;
struct Box { vec4 minimum; vec4 maximum; };
layout(std430, binding = 0) readonly buffer Boxes { Box boxes[]; };
layout(std430, binding = 1) writeonly buffer Entries { uvec2 entries[]; };
uniform uint slotCount;
uniform uint paddedCount;
uniform uint axis;

// Unsigned order equals float order (but -0 before +0, harmless: the sweep
// compares the floats themselves).
uint orderedKey(float value) {
  uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : (bits | 0x80000000u);
}

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= paddedCount) return;
  uint key = 0xffffffffu;
  if (slot < slotCount && boxes[slot].minimum.w != 0.0) key = orderedKey(boxes[slot].minimum[axis]);
  entries[slot] = uvec2(key, slot);
}
)glsl";

const char* const broadPhaseLocalSortShader = R"glsl(#version 430
layout(local_size_x = 256) in;
layout(std430, binding = 1) buffer Entries { uvec2 entries[]; };
uniform uint mergeStage;
shared uvec2 block[512];

// Ties on the key fall back to the slot: the order is the same on every run.
bool after(uvec2 first, uvec2 second) {
  return first.x > second.x || (first.x == second.x && first.y > second.y);
}

void main() {
  uint base = gl_WorkGroupID.x * 512u;
  uint thread = gl_LocalInvocationID.x;
  block[thread] = entries[base + thread];
  block[thread + 256u] = entries[base + thread + 256u];
  barrier();
  uint firstStage = mergeStage == 0u ? 2u : mergeStage;
  uint lastStage = mergeStage == 0u ? 512u : mergeStage;
  for (uint stage = firstStage; stage <= lastStage; stage <<= 1) {
    for (uint step = min(stage, 512u) >> 1; step > 0u; step >>= 1) {
      uint low = 2u * step * (thread / step) + thread % step;
      uint high = low + step;
      bool ascending = ((base + low) & stage) == 0u;
      uvec2 first = block[low];
      uvec2 second = block[high];
      if (after(first, second) == ascending) {
        block[low] = second;
        block[high] = first;
      }
      barrier();
    }
  }
  entries[base + thread] = block[thread];
  entries[base + thread + 256u] = block[thread + 256u];
}
)glsl";

const char* const broadPhaseGlobalStepShader = R"glsl(#version 430
layout(local_size_x = 256) in;
layout(std430, binding = 1) buffer Entries { uvec2 entries[]; };
uniform uint stage;
uniform uint step;

bool after(uvec2 first, uvec2 second) {
  return first.x > second.x || (first.x == second.x && first.y > second.y);
}

void main() {
  uint thread = gl_GlobalInvocationID.x;
  uint low = 2u * step * (thread / step) + thread % step;
  uint high = low + step;
  bool ascending = (low & stage) == 0u;
  uvec2 first = entries[low];
  uvec2 second = entries[high];
  if (after(first, second) == ascending) {
    entries[low] = second;
    entries[high] = first;
  }
}
)glsl";

const char* const broadPhaseGatherShader = R"glsl(#version 430
layout(local_size_x = 256) in;
struct Box { vec4 minimum; vec4 maximum; };
layout(std430, binding = 0) readonly buffer Boxes { Box boxes[]; };
layout(std430, binding = 1) readonly buffer Entries { uvec2 entries[]; };
layout(std430, binding = 3) writeonly buffer Sorted { Box sorted[]; };
uniform uint liveCount;

void main() {
  uint position = gl_GlobalInvocationID.x;
  if (position >= liveCount) return;
  uint slot = entries[position].y;
  Box box = boxes[slot];
  box.maximum.w = uintBitsToFloat(slot);
  sorted[position] = box;
}
)glsl";

const char* const broadPhaseSweepShader = R"glsl(#version 430
layout(local_size_x = 256) in;
struct Box { vec4 minimum; vec4 maximum; };
layout(std430, binding = 2) buffer Pairs { uint pairCount; uint padding; uvec2 pairs[]; };
layout(std430, binding = 3) readonly buffer Sorted { Box sorted[]; };
uniform uint liveCount;
uniform uint axis;
uniform uint capacity;

void main() {
  uint position = gl_GlobalInvocationID.x;
  if (position >= liveCount) return;
  Box box = sorted[position];
  uint self = floatBitsToUint(box.maximum.w);
  float reach = box.maximum[axis];
  bool drives = box.minimum.w == 2.0;
  for (uint next = position + 1u; next < liveCount; ++next) {
    Box candidate = sorted[next];
    if (candidate.minimum[axis] > reach) break;
    if (!drives && candidate.minimum.w != 2.0) continue;
    if (all(lessThanEqual(box.minimum.xyz, candidate.maximum.xyz)) &&
        all(lessThanEqual(candidate.minimum.xyz, box.maximum.xyz))) {
      uint other = floatBitsToUint(candidate.maximum.w);
      uint slot = atomicAdd(pairCount, 1u);
      if (slot < capacity) pairs[slot] = uvec2(min(self, other), max(self, other));
    }
  }
}
)glsl";

}  // namespace physdbg::gpu
