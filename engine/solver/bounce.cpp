#include "engine/solver/bounce.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace physdbg {
namespace {

// Share of the largest magnitude involved that a total may fall below zero
// and still count as pushing: far above the rounding of a 4x4 product.
constexpr double kRounding = 1e-9;

// The root u >= 0 of u^2/2 - half u = energy (0 when there is none).
double speedForEnergy(double energy, double half) {
  return std::max(0.0, half + std::sqrt(std::max(0.0, half * half + 2.0 * energy)));
}

}  // namespace

double bounceSpeed(const BounceInput& input) {
  const double pull = input.pull, v0 = input.startVelocity, e = input.restitution;
  const double half = 0.5 * pull * input.substep;
  // The energy it arrives with at x = 0, where the potential is zero.
  const double arriving = 0.5 * v0 * v0 + pull * std::max(0.0, input.startGap) - half * v0;
  // Leaving: v = u at x_end with e^2 of it, u^2/2 - half u + pull x_end = e^2 arriving.
  return speedForEnergy(e * e * arriving - pull * input.endGap, half);
}

Eigen::Matrix4d normalMassMatrix(const ContactManifold& manifold, const PointConstraint* rows,
                                 const Vec3& linearMaskA, const Vec3& linearMaskB) {
  const Vec3& normal = manifold.normal;
  Eigen::Matrix4d mass = Eigen::Matrix4d::Zero();
  if (manifold.pointCount == 0) return mass;
  const double linear = rows[0].inverseMassA * normal.cwiseProduct(linearMaskA).dot(normal) +
                        rows[0].inverseMassB * normal.cwiseProduct(linearMaskB).dot(normal);
  for (int i = 0; i < manifold.pointCount; ++i)
    for (int j = 0; j < manifold.pointCount; ++j)
      mass(i, j) = linear + rows[i].crossA[0].dot(rows[j].turnA[0]) + rows[i].crossB[0].dot(rows[j].turnB[0]);
  return mass;
}

Eigen::Matrix4d pseudoInverse(const Eigen::Matrix4d& matrix) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(matrix);
  const Eigen::Vector4d values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  Eigen::Vector4d inverse = Eigen::Vector4d::Zero();
  for (int i = 0; i < 4; ++i)
    if (values[i] > 1e-9 * largest) inverse[i] = 1.0 / values[i];
  return eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
}

Eigen::Vector4d bounceImpulses(const Eigen::Matrix4d& mass, const Eigen::Vector4d& error,
                               const Eigen::Vector4d& impulse, int count, int mask) {
  const auto inside = [mask](int p) { return ((mask >> p) & 1) != 0; };
  Eigen::Matrix4d block = Eigen::Matrix4d::Identity();
  Eigen::Vector4d right = Eigen::Vector4d::Zero();
  double scale = 0.0;
  for (int i = 0; i < count; ++i) {
    if (!inside(i)) continue;
    right[i] = -error[i];
    scale = std::max({scale, std::abs(impulse[i])});
    for (int j = 0; j < count; ++j)
      if (inside(j)) block(i, j) = mass(i, j);
  }
  Eigen::Vector4d change = pseudoInverse(block) * right;
  for (int p = 0; p < 4; ++p)
    if (!inside(p)) change[p] = 0.0;
  scale = std::max(scale, change.cwiseAbs().maxCoeff());
  bool pulls = false;
  for (int p = 0; p < count; ++p) pulls = pulls || (inside(p) && impulse[p] + change[p] < -kRounding * scale);
  if (!pulls) return change;
  // Projected Gauss-Seidel from no change, to convergence: a few points, so
  // a few hundred sweeps at most cost nothing beside the step.
  change.setZero();
  for (int sweep = 0; sweep < 500; ++sweep) {
    double largest = 0.0;
    for (int p = 0; p < count; ++p) {
      if (!inside(p) || !(mass(p, p) > 0.0)) continue;
      const double velocityError = error[p] + mass.row(p).dot(change);
      const double next = std::max(impulse[p] + change[p] - velocityError / mass(p, p), 0.0) - impulse[p];
      largest = std::max(largest, std::abs(next - change[p]));
      change[p] = next;
    }
    if (largest <= 1e-15 * (scale + change.cwiseAbs().maxCoeff())) break;
  }
  return change;
}

}  // namespace physdbg
