#include "gpu/broad_phase_shaders.h"

#include <string>

namespace physdbg::gpu {

// The group size and block are spelled out in the sources; the static_assert
// keeps them equal to the constants the dispatches use.
static_assert(broadPhaseGroupSize == 256 && broadPhaseSortBlock == 512);

namespace {

// Every binding of the header comment, declared once for all the shaders.
constexpr const char* preamble = R"glsl(#version 430
layout(local_size_x = 256) in;
struct Box { vec4 minimum; vec4 maximum; };
layout(std430, binding = 0) buffer Boxes { Box boxes[]; };
layout(std430, binding = 1) buffer Entries { uvec2 entries[]; };
layout(std430, binding = 2) buffer Pairs { uint pairCount; uint padding; uvec2 pairs[]; };
layout(std430, binding = 3) buffer Sorted { Box sorted[]; };
layout(std430, binding = 4) buffer Links { uvec4 links[]; };
layout(std430, binding = 5) buffer Nodes { Box nodes[]; };

// Ties on the key fall back to the slot: the order is the same on every run.
bool after(uvec2 first, uvec2 second) {
  return first.x > second.x || (first.x == second.x && first.y > second.y);
}

bool overlapping(Box first, Box second) {
  return all(lessThanEqual(first.minimum.xyz, second.maximum.xyz)) &&
         all(lessThanEqual(second.minimum.xyz, first.maximum.xyz));
}
)glsl";

}  // namespace

std::string broadPhaseProgramSource(const char* body) { return std::string(preamble) + body; }

const char* const broadPhaseKeyShader = R"glsl(
uniform uint slotCount;
uniform uint paddedCount;
uniform vec3 origin;
uniform vec3 scale;

// Spreads the low 10 bits of value to every third bit.
uint spreadBits(uint value) {
  value &= 0x3ffu;
  value = (value | (value << 16)) & 0x030000ffu;
  value = (value | (value << 8)) & 0x0300f00fu;
  value = (value | (value << 4)) & 0x030c30c3u;
  value = (value | (value << 2)) & 0x09249249u;
  return value;
}

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= paddedCount) return;
  uint key = 0xffffffffu;  // above every 30-bit code
  if (slot < slotCount && boxes[slot].minimum.w != 0.0) {
    vec3 center = 0.5 * (boxes[slot].minimum.xyz + boxes[slot].maximum.xyz);
    uvec3 cell = uvec3(clamp((center - origin) * scale, vec3(0.0), vec3(1023.0)));
    key = spreadBits(cell.x) | (spreadBits(cell.y) << 1) | (spreadBits(cell.z) << 2);
  }
  entries[slot] = uvec2(key, slot);
}
)glsl";

const char* const broadPhaseLocalSortShader = R"glsl(
uniform uint mergeStage;
shared uvec2 block[512];

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

const char* const broadPhaseGlobalStepShader = R"glsl(
uniform uint stage;
uniform uint step;

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

const char* const broadPhaseGatherShader = R"glsl(
uniform uint liveCount;

void main() {
  uint position = gl_GlobalInvocationID.x;
  if (position >= liveCount) return;
  sorted[position] = boxes[entries[position].y];
}
)glsl";

const char* const broadPhaseBuildShader = R"glsl(
uniform int liveCount;

// Length of the common prefix of two sorted keys; equal keys go on with the
// positions, so every prefix is distinct. -1 outside the list.
int commonPrefix(int first, int second) {
  if (second < 0 || second >= liveCount) return -1;
  uint difference = entries[first].x ^ entries[second].x;
  if (difference == 0u) return 32 + 31 - findMSB(uint(first) ^ uint(second));
  return 31 - findMSB(difference);
}

void main() {
  int node = int(gl_GlobalInvocationID.x);
  if (node >= liveCount - 1) return;
  int direction = commonPrefix(node, node + 1) > commonPrefix(node, node - 1) ? 1 : -1;
  int floorPrefix = commonPrefix(node, node - direction);
  int bound = 2;
  while (commonPrefix(node, node + bound * direction) > floorPrefix) bound *= 2;
  int length = 0;
  for (int step = bound / 2; step >= 1; step /= 2) {
    if (commonPrefix(node, node + (length + step) * direction) > floorPrefix) length += step;
  }
  int other = node + length * direction;
  int nodePrefix = commonPrefix(node, other);
  int split = 0;
  for (int divisor = 2;; divisor *= 2) {
    int step = (length + divisor - 1) / divisor;
    if (commonPrefix(node, node + (split + step) * direction) > nodePrefix) split += step;
    if (step <= 1) break;
  }
  int gamma = node + split * direction + min(direction, 0);
  int first = min(node, other), last = max(node, other);
  uint left = first == gamma ? (uint(gamma) | 0x80000000u) : uint(gamma);
  uint right = last == gamma + 1 ? (uint(gamma + 1) | 0x80000000u) : uint(gamma + 1);
  links[node] = uvec4(left, right, uint(first), uint(last));
}
)glsl";

const char* const broadPhaseBoundsShader = R"glsl(
uniform uint liveCount;

void main() {
  uint node = gl_GlobalInvocationID.x;
  if (node + 1u >= liveCount) return;
  uvec4 link = links[node];
  vec3 low = sorted[link.z].minimum.xyz, high = sorted[link.z].maximum.xyz;
  float role = sorted[link.z].minimum.w;
  for (uint leaf = link.z + 1u; leaf <= link.w; ++leaf) {
    Box box = sorted[leaf];
    low = min(low, box.minimum.xyz);
    high = max(high, box.maximum.xyz);
    role = max(role, box.minimum.w);
  }
  nodes[node] = Box(vec4(low, role), vec4(high, 0.0));  // role 2: a proxy below drives pairs
}
)glsl";

const char* const broadPhaseTraverseShader = R"glsl(
uniform uint liveCount;
uniform uint capacity;

void main() {
  uint position = gl_GlobalInvocationID.x;
  if (position >= liveCount) return;
  Box box = sorted[position];
  uint self = entries[position].y;
  bool drives = box.minimum.w == 2.0;
  uint stack[64];
  int top = 0;
  stack[top++] = 0u;
  while (top > 0) {
    uvec4 link = links[stack[--top]];
    for (int side = 0; side < 2; ++side) {
      uint child = side == 0 ? link.x : link.y;
      if ((child & 0x80000000u) != 0u) {
        uint leaf = child & 0x7fffffffu;
        if (leaf <= position) continue;
        Box candidate = sorted[leaf];
        if ((drives || candidate.minimum.w == 2.0) && overlapping(box, candidate)) {
          uint other = entries[leaf].y;
          uint slot = atomicAdd(pairCount, 1u);
          if (slot < capacity) pairs[slot] = uvec2(min(self, other), max(self, other));
        }
      } else if (links[child].w > position) {
        Box bounds = nodes[child];
        if ((drives || bounds.minimum.w == 2.0) && overlapping(box, bounds)) stack[top++] = child;
      }
    }
  }
}
)glsl";

}  // namespace physdbg::gpu
