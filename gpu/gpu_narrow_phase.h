#pragma once
// The narrow phase of the pairs the GPU can answer, for many pairs at once:
// one dispatch and one readback per step instead of one CPU call per pair.
// It answers as collide() with default options and buildManifold() would
// (gpu_narrow_phase_test.cpp measures how closely), in float:
//  - Positions go up as two floats each (high part and remainder) and the
//    shader subtracts them pairwise, so a pair 1e4 m from the origin keeps
//    float's relative precision of its own size; points come back relative
//    to A's position and A's double position is added here.
//  - Float round-off is far above the CPU's double tie margins, so the
//    shader's are wider (narrow_phase_shader.cpp names each): exact ties
//    (stacks, equal boxes) resolve as on the CPU, but two axes or reference
//    faces within about 1e-6 of the pair's size of each other, or a point
//    within float round-off of a side plane or the reach, may be decided the
//    other way. A point's feature id then differs with it.
//  - Box pairs the separating-axis test cannot settle (separated, closest
//    features no axis names: the CPU asks GJK) and a sphere centre on a
//    capsule's core (the CPU asks EPA) are flagged by the shader and answered
//    by the CPU path here, so their results are the CPU's own;
//    lastTimings().cpuFallbacks counts them.
//  - A clipped polygon holds 8 points (the CPU's 16 leave room for
//    round-off bending a nearly edge-on face; a quad clipped by a rectangle
//    has at most 8), so such a pair may keep other points than the CPU.
//  - Touching and Penetrating may disagree with the CPU where the signed
//    distance is within float round-off of the touching tolerance.
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
