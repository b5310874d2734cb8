#pragma once
// The GLSL of the narrow phase on the GPU (gpu_narrow_phase.h), kept apart
// so the C++ around it reads on its own.
namespace physdbg::gpu {

// Storage bindings and record layouts the source expects; GpuNarrowPhase
// fills them (std430, every member a dvec4 or uvec4, placed so no padding
// arises; gpu_narrow_phase.cpp asserts the offsets).
enum NarrowPhaseBinding : unsigned { kPoseBinding = 0, kShapeBinding = 1, kRequestBinding = 2, kResultBinding = 3 };

const char* narrowPhaseShaderSource();

}  // namespace physdbg::gpu
