#include "gpu/gpu_narrow_phase.h"

#include <bit>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/contacts/manifold_points.h"
#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "gpu/narrow_phase_shader.h"
#include "render/gl_headers.h"

namespace physdbg::gpu {

// std430 with double vectors: a dvec4 is 32 bytes and aligned to 32, a
// uvec4 16; every member below is one of them, placed so no padding arises.
struct GpuPose {
  double position[4];  // w unused
  double rotation[4];  // unit quaternion xyzw
};
static_assert(sizeof(GpuPose) == 64 && offsetof(GpuPose, rotation) == 32);

struct GpuShape {
  double parameters[4];  // w: ColliderKind
  bool operator==(const GpuShape&) const = default;
};
static_assert(sizeof(GpuShape) == 32);

struct GpuNarrowPhase::GpuResult {
  double normal[4];  // w: signed distance
  double pointA[4], pointB[4];
  double manifoldNormal[4];  // w: point count
  double manifoldA[4][4];    // w: separation
  double manifoldB[4][4];
  std::uint32_t flags[4];
  std::uint32_t featureIds[4];
};

namespace {

constexpr unsigned kWorkGroupSize = 64;  // local_size_x in the shader
constexpr std::uint32_t kFlagBoxBox = 1, kFlagNeedsCpu = 2, kFlagPointsFromB = 4;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

GpuShape shapeOf(const Collider& collider) {
  GpuShape shape{{0, 0, 0, static_cast<double>(static_cast<int>(collider.kind()))}};
  switch (collider.kind()) {
    case ColliderKind::Sphere: shape.parameters[0] = static_cast<const SphereCollider&>(collider).radius(); break;
    case ColliderKind::Box: {
      const Vec3& half = static_cast<const BoxCollider&>(collider).halfExtents();
      for (int i = 0; i < 3; ++i) shape.parameters[i] = half[i];
      break;
    }
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      shape.parameters[0] = capsule.radius();
      shape.parameters[1] = capsule.halfHeight();
      break;
    }
    default: break;  // not supported: never requested
  }
  return shape;
}

// The rotation normalised as collide() normalises it, so both start from the same quaternion.
GpuPose poseOf(const Transform& transform) {
  const Quat rotation = transform.rotation.normalized();
  return {{transform.position.x(), transform.position.y(), transform.position.z(), 0.0},
          {rotation.x(), rotation.y(), rotation.z(), rotation.w()}};
}

bool sameTransform(const Transform& a, const Transform& b) {
  return a.position == b.position && a.rotation.coeffs() == b.rotation.coeffs();
}

// Uploads the runs of consecutive records whose `changed` is true; returns how many went up.
template <class Record>
int uploadChanged(StorageBuffer& buffer, const std::vector<Record>& records, const std::vector<bool>& changed) {
  int uploaded = 0;
  for (std::size_t start = 0; start < records.size();) {
    if (!changed[start]) {
      ++start;
      continue;
    }
    std::size_t end = start;
    while (end < records.size() && changed[end]) ++end;
    buffer.upload(start * sizeof(Record), &records[start], (end - start) * sizeof(Record));
    uploaded += static_cast<int>(end - start);
    start = end;
  }
  return uploaded;
}

Vec3 toVec3(const double* values) { return {values[0], values[1], values[2]}; }

}  // namespace

GpuNarrowPhase::GpuNarrowPhase(ComputeContext& context) : context_(context) {
  context_.makeCurrent();
  program_ = render::createComputeProgram(narrowPhaseShaderSource(), "narrow phase");
}

// The program and buffers are GL names of this context.
GpuNarrowPhase::~GpuNarrowPhase() { context_.tryMakeCurrent(); }

bool GpuNarrowPhase::supports(ColliderKind a, ColliderKind b) {
  const auto sphereWith = [](ColliderKind other) {
    return other == ColliderKind::Sphere || other == ColliderKind::Box || other == ColliderKind::Capsule;
  };
  if (a == ColliderKind::Sphere) return sphereWith(b);
  if (b == ColliderKind::Sphere) return sphereWith(a);
  return a == ColliderKind::Box && b == ColliderKind::Box;
}

void GpuNarrowPhase::collide(const std::vector<RigidBody>& bodies, const std::vector<NarrowPhaseRequest>& requests,
                             std::vector<GpuContact>& out) {
  context_.makeCurrent();
  timings_ = {};
  const Clock::time_point start = Clock::now();
  uploadBodies(bodies);
  uploadRequests(bodies, requests);
  timings_.uploadSeconds = secondsSince(start);
  const Clock::time_point dispatched = Clock::now();
  dispatch(requests.size());
  timings_.dispatchSeconds = secondsSince(dispatched);
  const Clock::time_point readback = Clock::now();
  resultStaging_.resize(requests.size() * sizeof(GpuResult));
  results_.download(0, resultStaging_.data(), resultStaging_.size());
  timings_.readbackSeconds = secondsSince(readback);
  convert(bodies, requests, out);
}

void GpuNarrowPhase::uploadBodies(const std::vector<RigidBody>& bodies) {
  const std::size_t count = bodies.size();
  const std::size_t poseCapacity = poses_.capacity(), shapeCapacity = shapes_.capacity();
  poses_.reserve(count * sizeof(GpuPose));
  shapes_.reserve(count * sizeof(GpuShape));
  // A grown buffer kept nothing: everything goes up again.
  const bool posesLost = poses_.capacity() != poseCapacity, shapesLost = shapes_.capacity() != shapeCapacity;
  poseStaging_.resize(count);
  shapeStaging_.resize(count);
  std::vector<bool>& poseChanged = poseChanged_;
  std::vector<bool>& shapeChanged = shapeChanged_;
  poseChanged.assign(count, false);
  shapeChanged.assign(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    const Transform transform = bodies[i].transform();
    const GpuShape shape = shapeOf(bodies[i].collider());
    const bool known = i < uploadedTransforms_.size();
    poseChanged[i] = posesLost || !known || !sameTransform(uploadedTransforms_[i], transform);
    shapeChanged[i] = shapesLost || !known || !(uploadedShapes_[i] == shape);
    if (poseChanged[i]) poseStaging_[i] = poseOf(transform);
    shapeStaging_[i] = shape;
  }
  timings_.posesUploaded = uploadChanged(poses_, poseStaging_, poseChanged);
  uploadChanged(shapes_, shapeStaging_, shapeChanged);
  uploadedTransforms_.resize(count);
  for (std::size_t i = 0; i < count; ++i) uploadedTransforms_[i] = bodies[i].transform();
  uploadedShapes_ = shapeStaging_;
}

void GpuNarrowPhase::uploadRequests(const std::vector<RigidBody>& bodies,
                                    const std::vector<NarrowPhaseRequest>& requests) {
  requestStaging_.resize(requests.size() * 4);
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const NarrowPhaseRequest& request = requests[i];
    if (request.a >= request.b || request.b >= bodies.size())
      throw std::invalid_argument("GpuNarrowPhase: request " + std::to_string(i) + " needs body ids a < b < body count");
    if (!supports(bodies[request.a].collider().kind(), bodies[request.b].collider().kind()))
      throw std::invalid_argument("GpuNarrowPhase: request " + std::to_string(i) + " pairs shapes the GPU does not collide");
    const double reach = requests[i].reach;
    std::uint32_t reachWords[2];  // low word first, as the shader's packDouble2x32 takes them
    std::memcpy(reachWords, &reach, sizeof reachWords);
    static_assert(std::endian::native == std::endian::little);
    requestStaging_[4 * i] = requests[i].a;
    requestStaging_[4 * i + 1] = requests[i].b;
    requestStaging_[4 * i + 2] = reachWords[0];
    requestStaging_[4 * i + 3] = reachWords[1];
  }
  requests_.reserve(requestStaging_.size() * sizeof(std::uint32_t));
  requests_.upload(0, requestStaging_.data(), requestStaging_.size() * sizeof(std::uint32_t));
  results_.reserve(requests.size() * sizeof(GpuResult));
}

void GpuNarrowPhase::dispatch(std::size_t requestCount) {
  if (requestCount == 0) return;
  glUseProgram(program_.get());
  glUniform1ui(0, static_cast<GLuint>(requestCount));
  poses_.bind(kPoseBinding);
  shapes_.bind(kShapeBinding);
  requests_.bind(kRequestBinding);
  results_.bind(kResultBinding);
  glDispatchCompute(static_cast<GLuint>((requestCount + kWorkGroupSize - 1) / kWorkGroupSize), 1, 1);
  glFinish();
  render::checkGlError("narrow phase dispatch");
}

void GpuNarrowPhase::convert(const std::vector<RigidBody>& bodies, const std::vector<NarrowPhaseRequest>& requests,
                             std::vector<GpuContact>& out) {
  out.resize(requests.size());
  const auto* results = reinterpret_cast<const GpuResult*>(resultStaging_.data());
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const RigidBody& bodyA = bodies[requests[i].a];
    const RigidBody& bodyB = bodies[requests[i].b];
    GpuContact& contact = out[i];
    contact.manifold = ContactManifold{};
    contact.manifold.a = requests[i].a;
    contact.manifold.b = requests[i].b;
    if (results[i].flags[0] & kFlagNeedsCpu) {
      const Transform ta = bodyA.transform(), tb = bodyB.transform();
      contact.result = physdbg::collide(bodyA.collider(), ta, bodyB.collider(), tb);
      buildManifold(bodyA.collider(), ta, bodyB.collider(), tb, contact.result, requests[i].reach, scratch_,
                    contact.manifold);
      ++timings_.cpuFallbacks;
    } else {
      fromShader(results[i], bodyA.transform(), bodyB.transform(), contact);
    }
  }
}

// Points come relative to A's position (manifold points of a face of B:
// to B's); that double position goes back on here, as the CPU adds it.
void GpuNarrowPhase::fromShader(const GpuResult& gpu, const Transform& ta, const Transform& tb, GpuContact& contact) {
  static_assert(offsetof(GpuResult, manifoldNormal) == 96 && offsetof(GpuResult, manifoldA) == 128 &&
                offsetof(GpuResult, manifoldB) == 256 && offsetof(GpuResult, flags) == 384 &&
                offsetof(GpuResult, featureIds) == 400 && sizeof(GpuResult) == 416);  // the shader's std430 layout
  const Vec3& origin = ta.position;
  contact.result = classifyContact(gpu.normal[3], toVec3(gpu.normal), origin + toVec3(gpu.pointA),
                                   origin + toVec3(gpu.pointB), NarrowPhaseOptions{}.touchingTolerance);
  contact.result.usedBoxBox = (gpu.flags[0] & kFlagBoxBox) != 0;
  ContactManifold& manifold = contact.manifold;
  manifold.normal = toVec3(gpu.manifoldNormal);
  manifold.pointCount = static_cast<int>(gpu.manifoldNormal[3]);
  if (gpu.featureIds[0] == 0) {  // the narrow phase's own point, as singlePoint() makes it
    manifold.normal = contact.result.normal;
    manifold.pointCount = 0;
    addPoint(manifold, ta, tb, contact.result.pointA, contact.result.pointB, 0);
    return;
  }
  const Vec3& manifoldOrigin = (gpu.flags[0] & kFlagPointsFromB) != 0 ? tb.position : origin;
  for (int k = 0; k < manifold.pointCount; ++k) {
    ManifoldPoint& point = manifold.points[k];
    point = ManifoldPoint{};
    point.pointA = manifoldOrigin + toVec3(gpu.manifoldA[k]);
    point.pointB = manifoldOrigin + toVec3(gpu.manifoldB[k]);
    point.localA = ta.applyInverse(point.pointA);
    point.localB = tb.applyInverse(point.pointB);
    point.separation = gpu.manifoldA[k][3];
    point.featureId = gpu.featureIds[k];
  }
}

}  // namespace physdbg::gpu
