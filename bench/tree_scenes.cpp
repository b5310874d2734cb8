#include <cmath>
#include <random>

#include "bench/tree_bench_support.h"

namespace physdbg::bench {

std::vector<Aabb> tilesScene() {
  std::vector<Aabb> boxes;
  const Vec3 half = Vec3::Constant(0.5);
  for (int row = 0; row < 10; ++row) {
    for (int column = 0; column < 200; ++column) {
      boxes.push_back(Aabb::fromCenterHalfExtents(Vec3(column - 100.0, -row, 0.0), half));
    }
  }
  for (int level = 0; level < 20; ++level) {
    const int count = 20 - level;
    for (int i = 0; i < count; ++i) {
      const Vec3 center(i - 0.5 * (count - 1), 1.0 + level, 0.0);
      boxes.push_back(Aabb::fromCenterHalfExtents(center, half));
    }
  }
  return boxes;
}

double cubeSideFor(int count) { return std::cbrt(8.0 * count); }

std::vector<Aabb> boxesInCube(int count, unsigned seed) {
  std::mt19937 random(seed);
  const double side = cubeSideFor(count);
  std::uniform_real_distribution<double> position(0.5, side - 0.5);
  std::vector<Aabb> boxes;
  boxes.reserve(count);
  for (int i = 0; i < count; ++i) {
    const Vec3 center(position(random), position(random), position(random));
    boxes.push_back(Aabb::fromCenterHalfExtents(center, Vec3::Constant(0.5)));
  }
  return boxes;
}

std::vector<Aabb> sortedLattice(int count) {
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(count))));
  std::vector<Aabb> boxes;
  for (int i = 0; i < count; ++i) {
    const Vec3 center(i % side, (i / side) % side, i / (side * side));
    boxes.push_back(Aabb::fromCenterHalfExtents(2.0 * center, Vec3::Constant(0.5)));
  }
  return boxes;
}

void jitter(std::vector<Aabb>& boxes, double step, double cubeSide, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-step, step);
  for (Aabb& box : boxes) {
    Vec3 shift(offset(random), offset(random), offset(random));
    for (int axis = 0; axis < 3; ++axis) {
      if (box.min[axis] + shift[axis] < 0.0 || box.max[axis] + shift[axis] > cubeSide) shift[axis] = -shift[axis];
    }
    box.min += shift;
    box.max += shift;
  }
}

}  // namespace physdbg::bench
