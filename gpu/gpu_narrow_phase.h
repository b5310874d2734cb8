#pragma once
// The narrow phase of the pairs the GPU can answer, for many pairs at once:
// one dispatch and one readback per step instead of one CPU call per pair.
// It answers as collide() with default options and buildManifold() would
// (gpu_narrow_phase_test.cpp measures how closely), in double precision:
//  - Why double: in float the shader could not follow the CPU's decisions on
//    resting piles. Boxes tilted 1e-5..1e-4 rad against each other have
//    nearly parallel edges whose cross products the CPU still tries as axes
//    (down to a sine of 1e-8), and axes, reference faces and reduction
//    candidates that tie to within 1e-10..1e-9 of the pair's size, which the
//    CPU settles by margins float round-off (1e-7) swamps: normals came out
//    1e-3 apart, manifold points on other corners, feature ids differed.
//    The shader now uses the CPU's own constants (narrow_phase_shader.cpp)
//    and its order of operations where that decides.
//  - What it costs: consumer GPUs run fp64 at 1/16..1/64 of their float rate
//    (data-centre parts at 1/2), and every record is twice the size. The
//    narrow phase is a small part of a step, and llvmpipe (the CPU) runs
//    doubles at nearly float speed.
//  - Positions and unit quaternions go up as doubles, results come back as
//    doubles. Points come back relative to A's position (a manifold on B's
//    face: to B's) and that position is added here, as the CPU adds it.
//  - Box pairs the separating-axis test cannot settle (separated, closest
//    features no axis names: the CPU asks GJK) and a sphere centre on a
//    capsule's core (the CPU asks EPA) are flagged by the shader and answered
//    by the CPU path here, so their results are the CPU's own;
//    lastTimings().cpuFallbacks counts them. Sphere-capsule pairs are
//    answered in closed form where the CPU runs GJK (which ends exactly on a
//    point against a segment: they agree to round-off in the tests).
//  - What may still differ: a decision the CPU takes on an exact tie in
//    exact arithmetic, settled by the last bit of round-off (a point exactly
//    on a clip plane plus its tolerance, two reduction candidates exactly
//    one margin apart), where the GPU's operation order or fused
//    multiply-adds differ from the compiled C++ (dot products, matrix
//    products and points made relative to A's position rather than absolute
//    round differently in the last bit).
#include <cstdint>
#include <vector>

#include "engine/collision_offload.h"
#include "engine/colliders/collider.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/contacts/manifold_builder.h"
#include "engine/dynamics/rigid_body.h"
#include "gpu/compute_context.h"
#include "gpu/storage_buffer.h"
#include "render/gl_objects.h"

namespace physdbg::gpu {

// The world's own request and answer (engine/collision_offload.h).
using NarrowPhaseRequest = OffloadRequest;
using GpuContact = OffloadedContact;

struct GpuNarrowPhaseTimings {
  double uploadSeconds = 0, dispatchSeconds = 0, readbackSeconds = 0;
  int posesUploaded = 0;
  int cpuFallbacks = 0;  // pairs the shader flagged and the CPU path answered (see above)
};

// Records as the shader reads them (narrow_phase_shader.cpp); defined in
// gpu_narrow_phase.cpp, the only place that fills them.
struct GpuPose;
struct GpuShape;

class GpuNarrowPhase {
 public:
  // Compiles the program; throws std::runtime_error with the log on failure.
  explicit GpuNarrowPhase(ComputeContext& context);
  ~GpuNarrowPhase();
  GpuNarrowPhase(const GpuNarrowPhase&) = delete;
  GpuNarrowPhase& operator=(const GpuNarrowPhase&) = delete;

  // Sphere-sphere, sphere-box, sphere-capsule, box-box (either order).
  // Anything else (convex meshes, capsule-capsule, capsule-box) stays on the CPU.
  static bool supports(ColliderKind a, ColliderKind b);

  // out[i] answers requests[i]. Throws std::invalid_argument for a request
  // that is not supported or names a body out of range. Makes the context
  // current. Shapes go up when a body is first seen or its collider
  // changes, poses when its transform changed since the last call.
  void collide(const std::vector<RigidBody>& bodies, const std::vector<NarrowPhaseRequest>& requests,
               std::vector<GpuContact>& out);
  const GpuNarrowPhaseTimings& lastTimings() const { return timings_; }

 private:
  void uploadBodies(const std::vector<RigidBody>& bodies);
  void uploadRequests(const std::vector<RigidBody>& bodies, const std::vector<NarrowPhaseRequest>& requests);
  void dispatch(std::size_t requestCount);
  void convert(const std::vector<RigidBody>& bodies, const std::vector<NarrowPhaseRequest>& requests,
               std::vector<GpuContact>& out);
  struct GpuResult;
  static void fromShader(const GpuResult& gpu, const Transform& ta, const Transform& tb, GpuContact& contact);

  ComputeContext& context_;
  render::GlProgram program_;
  StorageBuffer poses_{"narrow phase poses"}, shapes_{"narrow phase shapes"};
  StorageBuffer requests_{"narrow phase requests"}, results_{"narrow phase results"};
  // What the buffers hold, to upload only what changed.
  std::vector<Transform> uploadedTransforms_;
  std::vector<GpuShape> uploadedShapes_;
  std::vector<GpuPose> poseStaging_;
  std::vector<GpuShape> shapeStaging_;
  std::vector<bool> poseChanged_, shapeChanged_;
  std::vector<std::uint32_t> requestStaging_;
  std::vector<unsigned char> resultStaging_;
  ManifoldScratch scratch_;
  GpuNarrowPhaseTimings timings_;
};

}  // namespace physdbg::gpu
