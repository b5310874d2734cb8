#pragma once
// Axis-aligned bounding box. Surface area (not volume, not perimeter) is the
// cost metric of the broad-phase tree: the chance that a random ray or box hits
// a convex volume is proportional to its surface area.
#include <algorithm>

#include "engine/math.h"

namespace physdbg {

struct Aabb {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();

  static Aabb fromCenterHalfExtents(const Vec3& center, const Vec3& half) {
    return {center - half, center + half};
  }

  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 halfExtents() const { return 0.5 * (max - min); }

  double surfaceArea() const {
    const Vec3 d = max - min;
    return 2.0 * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
  }

  bool overlaps(const Aabb& other) const {
    return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
  }

  bool contains(const Aabb& other) const {
    return (min.array() <= other.min.array()).all() && (other.max.array() <= max.array()).all();
  }

  Aabb merged(const Aabb& other) const { return {min.cwiseMin(other.min), max.cwiseMax(other.max)}; }

  Aabb enlarged(double margin) const {
    const Vec3 m = Vec3::Constant(margin);
    return {min - m, max + m};
  }

  bool isValid() const { return min.allFinite() && max.allFinite() && (min.array() <= max.array()).all(); }
};

}  // namespace physdbg
