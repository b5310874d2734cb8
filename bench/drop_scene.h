#pragma once
// The "drop" benchmark scene (see /work/shared/NOTES.md, "Peer baseline"):
// N unit spheres (radius 0.5) or unit cubes, mass 1, restitution 0.2,
// friction 0.5, on a grid with 1.2 m spacing over a square footprint of
// ceil(sqrt(N/4)) cells, layers upwards from y = 1, dropped into an open
// container (floor plus four walls). Sleeping is off.
//
// Jittered (the default): dropped body i (0-based) moves sideways by
//   0.05 m * (u(2i), 0, u(2i + 1)),  u(k) = 2 * (splitmix64(k) >> 11) / 2^53 - 1,
// splitmix64 being Vigna's 64-bit mix (https://prng.di.unimi.it/splitmix64.c)
// of k. Without it every body starts exactly above another, and a pile that
// double precision keeps balanced (columns of spheres, exactly N contacts) is
// not the pile another engine's round-off topples: not the same work. The
// offsets are the same for every engine that is given the scene.
#include <cstdint>

#include "scenes/scene.h"

namespace physdbg::bench {

enum class DropShape { Sphere, Box };

struct DropContainer {
  double innerHalfWidth = 0.0;  // x and z, from the centre to a wall's inner face
  double wallTop = 0.0;         // y
};

struct DropScene {
  SceneDescription scene;  // bodies: floor, four walls, then the N dropped ones
  DropContainer container;
  int firstDropped = 5;
};

// Throws std::invalid_argument for count < 1.
DropScene dropScene(int count, DropShape shape, bool jittered = true);

// u(k) above: in [-1, 1), from k alone.
double dropJitter(std::uint64_t k);

// A body left the container when its centre is outside the walls or below
// the floor (0.01 m tolerance).
bool leftContainer(const Vec3& position, const DropContainer& container);

}  // namespace physdbg::bench
