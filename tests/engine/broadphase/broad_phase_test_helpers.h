#pragma once
// Scene makers shared by the tree and broad-phase tests. Fixed seeds; the
// std distributions are implementation-defined, which is fine for tests that
// compare against brute force on whatever boxes come out.
#include <cmath>
#include <random>
#include <vector>

#include "engine/aabb.h"

namespace physdbg::testing {

inline Aabb randomBox(std::mt19937& random, double worldSize, double maxHalfExtent) {
  std::uniform_real_distribution<double> position(-worldSize, worldSize);
  std::uniform_real_distribution<double> half(0.01, maxHalfExtent);
  const Vec3 center(position(random), position(random), position(random));
  return Aabb::fromCenterHalfExtents(center, Vec3(half(random), half(random), half(random)));
}

// Unit cubes on an integer lattice: neighbours touch exactly (shared faces), the
// case where a strict overlap test would drop pairs.
inline Aabb latticeBox(std::mt19937& random, int cells) {
  std::uniform_int_distribution<int> cell(0, cells - 1);
  const Vec3 corner(cell(random), cell(random), cell(random));
  return {corner, corner + Vec3::Ones()};
}

inline std::vector<Aabb> sortedRow(int count) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < count; ++i) boxes.push_back(Aabb::fromCenterHalfExtents(Vec3(i, 0, 0), Vec3::Constant(0.5)));
  return boxes;
}

inline std::vector<Aabb> sortedGrid(int side) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) boxes.push_back(Aabb::fromCenterHalfExtents(Vec3(i, j, 0), Vec3::Constant(0.5)));
  }
  return boxes;
}

}  // namespace physdbg::testing
