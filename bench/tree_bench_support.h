#pragma once
// Scenes and timing shared by the tree benchmark's cases.
#include <chrono>
#include <vector>

#include "engine/aabb.h"

namespace physdbg::bench {

template <typename Work>
double millisecondsOf(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Box2D's "tiles" scene lifted to 3D: 200 x 10 unit tiles in sorted order,
// then a 20-row pyramid of unit boxes on top (2210 boxes).
std::vector<Aabb> tilesScene();

// Unit cubes spread uniformly in a cube of about 8 volume units per box.
std::vector<Aabb> boxesInCube(int count, unsigned seed);

// Unit cubes on a lattice, in sorted (x fastest) order.
std::vector<Aabb> sortedLattice(int count);

// Every box shifted by up to +-step per axis, bounced back into the cube.
void jitter(std::vector<Aabb>& boxes, double step, double cubeSide, unsigned seed);

double cubeSideFor(int count);

}  // namespace physdbg::bench
