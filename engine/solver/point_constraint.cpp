#include "engine/solver/point_constraint.h"

namespace physdbg {
namespace {

// 1 / (J M^-1 J^T) of one row, from the row's cross and turn vectors: the
// turn is what the row's impulse does to the spin, so a locked axis (masked
// out of the turn) adds no give, as it adds no motion.
double rowMass(double inverseMassSum, const PointConstraint& c, int row) {
  const double k = inverseMassSum + c.crossA[row].dot(c.turnA[row]) + c.crossB[row].dot(c.turnB[row]);
  return k > 0.0 ? 1.0 / k : 0.0;
}

// inertia * v, each row summed left to right, then masked: spelled out so
// the SIMD build (wide_constraint_build.cpp) repeats it operation for
// operation. Eigen's own 3x3 product sums its last row in another order.
Vec3 maskedProduct(const Mat3& inertia, const Vec3& v, const Vec3& mask) {
  Vec3 result;
  for (int i = 0; i < 3; ++i)
    result[i] = (inertia(i, 0) * v[0] + inertia(i, 1) * v[1] + inertia(i, 2) * v[2]) * mask[i];
  return result;
}

}  // namespace

namespace {

// rotation^T * v, each component summed left to right.
Vec3 transposedProduct(const Mat3& rotation, const Vec3& v) {
  Vec3 result;
  for (int i = 0; i < 3; ++i) result[i] = rotation(0, i) * v[0] + rotation(1, i) * v[1] + rotation(2, i) * v[2];
  return result;
}

}  // namespace

void pointGaps(const ContactManifold& manifold, const Vec3& positionA, const Mat3& rotationA, const Vec3& positionB,
               const Mat3& rotationB, double* gaps) {
  const double centres = (positionB - positionA).dot(manifold.normal);
  const Vec3 normalInA = transposedProduct(rotationA, manifold.normal);
  const Vec3 normalInB = transposedProduct(rotationB, manifold.normal);
  for (int p = 0; p < manifold.pointCount; ++p) {
    const ManifoldPoint& point = manifold.points[p];
    gaps[p] = centres + (normalInB.dot(point.localB) - normalInA.dot(point.localA));
  }
}

// Touching or overlapping, both bodies push at the midpoint. A speculative
// point may still be metres from the other body; there each pushes at its
// own surface, or friction gets a long lever.
void pointArms(const ContactManifold& manifold, int p, const Vec3& positionA, const Vec3& positionB, double linearSlop,
               Vec3& armA, Vec3& armB) {
  const ManifoldPoint& point = manifold.points[p];
  const bool apart = point.separation > linearSlop;
  const Vec3 middle = 0.5 * (point.pointA + point.pointB);
  armA = (apart ? point.pointA : middle) - positionA;
  armB = (apart ? point.pointB : middle) - positionB;
}

void buildPointRows(const ManifoldFrame& frame, const ContactManifold& manifold, int p, int rows,
                    const ConstraintSettings& settings, PointConstraint& c) {
  pointArms(manifold, p, frame.positionA, frame.positionB, settings.linearSlop, c.armA, c.armB);
  for (int row = 0; row < rows; ++row) {
    c.crossA[row] = c.armA.cross(frame.directions[row]);
    c.crossB[row] = c.armB.cross(frame.directions[row]);
    c.turnA[row] = maskedProduct(frame.inverseInertiaA, c.crossA[row], frame.angularMaskA);
    c.turnB[row] = maskedProduct(frame.inverseInertiaB, c.crossB[row], frame.angularMaskB);
  }
  c.inverseMassA = frame.inverseMassA;
  c.inverseMassB = frame.inverseMassB;
  if (rows > 0) c.normalMass = rowMass(frame.inverseMassSum, c, 0);
  for (int t = 0; t + 1 < rows; ++t) c.tangentMass[t] = rowMass(frame.inverseMassSum, c, t + 1);
}

// Friction and restitution follow from the velocities at the start of the step.
void buildPointConstraints(const ManifoldFrame& frame, const ContactManifold& manifold,
                           const ConstraintSettings& settings, PointConstraint* out) {
  for (int p = 0; p < manifold.pointCount; ++p) {
    PointConstraint& c = out[p];
    buildPointRows(frame, manifold, p, 3, settings, c);
    const Vec3 relative = (frame.linearVelocityB + frame.angularVelocityB.cross(c.armB)) -
                          (frame.linearVelocityA + frame.angularVelocityA.cross(c.armA));
    c.approachVelocity = relative.dot(manifold.normal);
    const double slidingSpeed = (relative - c.approachVelocity * manifold.normal).norm();
    const CombinedMaterial& material = frame.material;
    c.friction = slidingSpeed < settings.stickingSpeed ? material.staticFriction : material.dynamicFriction;
    c.restitution = c.approachVelocity < -settings.restitutionThreshold ? material.restitution : 0.0;
    c.largestImpulse = 0.0;
    c.gap = 0.0;
  }
}

void maskLinearRows(const ManifoldFrame& frame, const Vec3& linearMaskA, const Vec3& linearMaskB, int rows,
                    PointConstraint& c) {
  for (int row = 0; row < rows; ++row) {
    const Vec3& d = frame.directions[row];
    const double give = frame.inverseMassA * d.cwiseProduct(linearMaskA).dot(d) +
                        frame.inverseMassB * d.cwiseProduct(linearMaskB).dot(d);
    const double mass = rowMass(give, c, row);
    if (row == 0)
      c.normalMass = mass;
    else
      c.tangentMass[row - 1] = mass;
  }
}

}  // namespace physdbg
