#pragma once
// The "drop" benchmark scene (see /work/shared/NOTES.md, "Peer baseline"):
// N unit spheres (radius 0.5) or unit cubes, mass 1, restitution 0.2,
// friction 0.5, on a grid with 1.2 m spacing over a square footprint of
// ceil(sqrt(N/4)) cells, layers upwards from y = 1, dropped into an open
// container (floor plus four walls). Sleeping is off.
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
DropScene dropScene(int count, DropShape shape);

// A body left the container when its centre is outside the walls or below
// the floor (0.01 m tolerance).
bool leftContainer(const Vec3& position, const DropContainer& container);

}  // namespace physdbg::bench
