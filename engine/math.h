#pragma once
// Shared maths vocabulary. Double precision everywhere in the engine: scenes far
// from the origin (1e7 m) must keep millimetre-level relative positions.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace physdbg {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// A rigid transform: world = position + rotation * local.
struct Transform {
  Vec3 position = Vec3::Zero();
  Quat rotation = Quat::Identity();

  Vec3 apply(const Vec3& local) const { return position + rotation * local; }
  Vec3 applyInverse(const Vec3& world) const { return rotation.conjugate() * (world - position); }
};

inline bool isFinite(const Vec3& v) { return v.allFinite(); }
inline bool isFinite(const Quat& q) { return q.coeffs().allFinite(); }

}  // namespace physdbg
