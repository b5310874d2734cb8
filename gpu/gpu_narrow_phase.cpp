#include "gpu/gpu_narrow_phase.h"

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "gpu/narrow_phase_shader.h"
#include "render/gl_headers.h"

namespace physdbg::gpu {

struct GpuPose {
  float high[4], low[4], rotation[4];  // position as high part and remainder; unit quaternion xyzw
};

struct GpuShape {
  float parameters[4];  // w: ColliderKind
  bool operator==(const GpuShape&) const = default;
};

struct GpuNarrowPhase::GpuResult {
  float normal[4];  // w: signed distance
  float pointA[4], pointB[4];
  float manifoldNormal[4];  // w: point count
  std::uint32_t flags[4];
  float manifoldA[4][4];  // w: separation
  float manifoldB[4][4];
  std::uint32_t featureIds[4];
};

namespace {

constexpr unsigned kWorkGroupSize = 64;  // local_size_x in the shader
constexpr std::uint32_t kFlagBoxBox = 1, kFlagNeedsCpu = 2;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

GpuShape shapeOf(const Collider& collider) {
  GpuShape shape{{0, 0, 0, static_cast<float>(static_cast<int>(collider.kind()))}};
  switch (collider.kind()) {
    case ColliderKind::Sphere: shape.parameters[0] = static_cast<float>(static_cast<const SphereCollider&>(collider).radius()); break;
    case ColliderKind::Box: {
      const Vec3& half = static_cast<const BoxCollider&>(collider).halfExtents();
      for (int i = 0; i < 3; ++i) shape.parameters[i] = static_cast<float>(half[i]);
      break;
    }
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      shape.parameters[0] = static_cast<float>(capsule.radius());
      shape.parameters[1] = static_cast<float>(capsule.halfHeight());
      break;
    }
    default: break;  // not supported: never requested
  }
  return shape;
}

// A double as a high part with float's 24 bits and the remainder: their
// sum carries about 48 bits. The high part comes from Veltkamp's split, not
// from double(float(value)): GCC 12.2 at -O3 vectorizes that round trip
// into nothing (the remainder came out zero for two of three coordinates).
void splitDouble(double value, float& high, float& low) {
  constexpr double splitter = 536870913.0;  // 2^29 + 1: keeps 53 - 29 = 24 bits
  const double scaled = value * splitter;
  const double rounded = scaled - (scaled - value);
  high = static_cast<float>(rounded);  // exact
  low = static_cast<float>(value - rounded);
}

GpuPose poseOf(const Transform& transform) {
  GpuPose pose{};
  const Quat rotation = transform.rotation.normalized();
  for (int i = 0; i < 3; ++i) splitDouble(transform.position[i], pose.high[i], pose.low[i]);
  const float quaternion[4] = {static_cast<float>(rotation.x()), static_cast<float>(rotation.y()),
                               static_cast<float>(rotation.z()), static_cast<float>(rotation.w())};
  std::memcpy(pose.rotation, quaternion, sizeof quaternion);
  return pose;
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

Vec3 toVec3(const float* values) { return {values[0], values[1], values[2]}; }

}  // namespace

GpuNarrowPhase::GpuNarrowPhase(ComputeContext& context) : context_(context) {
  context_.makeCurrent();
  program_ = render::createComputeProgram(narrowPhaseShaderSource(), "narrow phase");
}

// The program and buffers are GL names of this context.
GpuNarrowPhase::~GpuNarrowPhase() { context_.makeCurrent(); }

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
    const float reach = static_cast<float>(requests[i].reach);
    std::uint32_t reachBits;
    std::memcpy(&reachBits, &reach, sizeof reachBits);
    requestStaging_[4 * i] = requests[i].a;
    requestStaging_[4 * i + 1] = requests[i].b;
    requestStaging_[4 * i + 2] = reachBits;
    requestStaging_[4 * i + 3] = 0;
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

// Points come relative to A's position: A's double position goes back on here.
void GpuNarrowPhase::fromShader(const GpuResult& gpu, const Transform& ta, const Transform& tb, GpuContact& contact) {
  const Vec3& origin = ta.position;
  contact.result = classifyContact(gpu.normal[3], toVec3(gpu.normal).normalized(), origin + toVec3(gpu.pointA),
                                   origin + toVec3(gpu.pointB), NarrowPhaseOptions{}.touchingTolerance);
  contact.result.usedBoxBox = (gpu.flags[0] & kFlagBoxBox) != 0;
  ContactManifold& manifold = contact.manifold;
  manifold.normal = toVec3(gpu.manifoldNormal).normalized();
  manifold.pointCount = static_cast<int>(gpu.manifoldNormal[3]);
  for (int k = 0; k < manifold.pointCount; ++k) {
    ManifoldPoint& point = manifold.points[k];
    point.pointA = origin + toVec3(gpu.manifoldA[k]);
    point.pointB = origin + toVec3(gpu.manifoldB[k]);
    point.localA = ta.applyInverse(point.pointA);
    point.localB = tb.applyInverse(point.pointB);
    point.separation = gpu.manifoldA[k][3];
    point.featureId = gpu.featureIds[k];
  }
}

}  // namespace physdbg::gpu
