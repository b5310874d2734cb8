#include "engine/narrowphase/narrow_phase.h"

#include <optional>
#include <stdexcept>

#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/box_box_contact.h"
#include "engine/narrowphase/epa.h"
#include "engine/narrowphase/gjk.h"

namespace physdbg {
namespace {

void validate(const Transform& ta, const Transform& tb, const NarrowPhaseOptions& options) {
  if (!isFinite(ta.position) || !isFinite(ta.rotation) || !isFinite(tb.position) || !isFinite(tb.rotation)) {
    throw std::invalid_argument("collide: transforms must be finite");
  }
  if (ta.rotation.squaredNorm() == 0.0 || tb.rotation.squaredNorm() == 0.0) {
    throw std::invalid_argument("collide: rotation quaternion must be non-zero");
  }
  if (!(options.touchingTolerance >= 0.0) || !(options.relativeTolerance >= 0.0) || options.maxGjkIterations < 1 ||
      options.maxEpaFaces < 4) {
    throw std::invalid_argument("collide: tolerances must be >= 0, maxGjkIterations >= 1 and maxEpaFaces >= 4");
  }
}

bool tryFastPath(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb, double tolerance,
                 ContactResult& result) {
  const auto kindA = a.kind(), kindB = b.kind();
  if (kindA == ColliderKind::Sphere && kindB == ColliderKind::Sphere) {
    result = collideSpheres(static_cast<const SphereCollider&>(a), ta.position, static_cast<const SphereCollider&>(b),
                            tb.position, tolerance);
    return true;
  }
  if (kindA == ColliderKind::Box && kindB == ColliderKind::Sphere) {
    result = collideBoxSphere(static_cast<const BoxCollider&>(a), ta, static_cast<const SphereCollider&>(b), tb.position,
                              tolerance);
    return true;
  }
  if (kindA == ColliderKind::Sphere && kindB == ColliderKind::Box) {
    result = swapped(collideBoxSphere(static_cast<const BoxCollider&>(b), tb, static_cast<const SphereCollider&>(a),
                                      ta.position, tolerance));
    return true;
  }
  return false;
}

// GJK/EPA in A's local frame; margins (sphere and capsule radii) are added
// along the core normal afterwards.
ContactResult generalPath(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                          const NarrowPhaseOptions& options) {
  const Mat3 rotationA = ta.rotation.toRotationMatrix();
  const Mat3 rotationB = rotationA.transpose() * tb.rotation.toRotationMatrix();
  SupportShape shapeA(a, Mat3::Identity(), Vec3::Zero());
  SupportShape shapeB(b, rotationB, rotationA.transpose() * (tb.position - ta.position));
  const GjkResult gjk = runGjk(shapeA, shapeB, options);
  Vec3 normal, pointA, pointB;
  double coreDistance;
  int epaIterations = 0;
  if (!gjk.overlapping) {
    normal = -gjk.closest / gjk.distance;
    coreDistance = gjk.distance;
    pointA = gjk.pointA;
    pointB = gjk.pointB;
  } else {
    const EpaResult epa = runEpa(gjk.simplex, shapeA, shapeB, options);
    normal = epa.normal;
    coreDistance = -epa.depth;
    pointA = epa.pointA;
    pointB = epa.pointB;
    epaIterations = epa.iterations;
  }
  pointA += shapeA.margin() * normal;
  pointB -= shapeB.margin() * normal;
  ContactResult result = classifyContact(coreDistance - shapeA.margin() - shapeB.margin(), rotationA * normal,
                                         ta.position + rotationA * pointA, ta.position + rotationA * pointB,
                                         options.touchingTolerance);
  result.gjkIterations = gjk.iterations;
  result.epaIterations = epaIterations;
  result.usedGeneralPath = true;
  return result;
}

}  // namespace

ContactResult collide(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                      const NarrowPhaseOptions& options) {
  validate(ta, tb, options);
  // Rotations are normalised once here so callers may pass slightly drifted quaternions.
  const Transform unitA{ta.position, ta.rotation.normalized()}, unitB{tb.position, tb.rotation.normalized()};
  ContactResult result;
  if (options.analyticFastPaths && tryFastPath(a, unitA, b, unitB, options.touchingTolerance, result)) return result;
  if (options.boxBoxSat && a.kind() == ColliderKind::Box && b.kind() == ColliderKind::Box) {
    if (std::optional<ContactResult> boxes = collideBoxes(static_cast<const BoxCollider&>(a), unitA,
                                                          static_cast<const BoxCollider&>(b), unitB,
                                                          options.touchingTolerance))
      return *boxes;
    // Separated with closest features no axis names: GJK gives the distance.
    result = generalPath(a, unitA, b, unitB, options);
    result.usedBoxBox = true;
    return result;
  }
  return generalPath(a, unitA, b, unitB, options);
}

}  // namespace physdbg
