#pragma once
// Small scenes with a closed-form or obvious right answer, for the stable
// contact acceptance tests (issue 6): mass-ratio stacks, a sliding block, a
// block on a slope, a bullet at a thin wall, a free tumbling box, deep initial
// overlap, an elastic drop. Sleeping is off in all of them: a sleeping body
// would hide the drift or jitter the tests look for. Body 0 is always the
// static ground (or wall) except in the tumbling box, which has nothing else.
// Every builder throws std::invalid_argument for out-of-range parameters.
#include <vector>

#include "scenes/scene.h"

namespace physdbg {

// Unit boxes stacked on a floor whose top is y = 0, with masses from the bottom
// up: body i + 1 has masses[i] and rests at y = 0.5 + i.
SceneDescription massStackScene(const std::vector<double>& masses);

// A unit box resting on a long floor (top y = 0), moving along +x at `speed`.
// Floor and block share the material, so the pair's coefficients are exactly
// the given ones (the solver combines materials by geometric mean).
SceneDescription slidingBlockScene(double speed, double dynamicFriction, double staticFriction);

// A static slab tilted by `angle` (radians, in (0, pi/2)) about +z, so its top
// face rises towards +x with normal (-sin, cos, 0); a unit box rests on that
// face with the same tilt. Both have static and dynamic friction `friction`.
// Body 1 is the block.
SceneDescription slopeScene(double angle, double friction);
Vec3 slopeDownhill(double angle);  // unit vector down the slope

enum class BulletShape { Sphere, Box };
// A small body (radius or half extent 0.05 m) 5 m left of a static 0.1 m thick
// wall whose near face is x = -0.05, flying along +x at `speed`; no gravity.
// Body 1 is the bullet.
SceneDescription bulletScene(double speed, BulletShape shape);
inline constexpr double bulletSize = 0.05;       // radius or half extent, m
inline constexpr double wallHalfThickness = 0.05;  // m

// One box (half extents 0.1, 0.2, 0.3, mass 1) spinning at (1, 2, 3) rad/s with
// no gravity and dt 0.01: MuJoCo's free tumbling-box test. Body 0.
SceneDescription tumblingBoxScene();

// Two unit boxes on the floor, the upper one sunk into the lower one by
// `overlapFraction` of its size. Bodies 1 (lower) and 2 (upper).
SceneDescription overlappingBoxesScene(double overlapFraction);

// A sphere of radius 0.5 with restitution 1 whose bottom starts `dropHeight`
// above the floor (top y = 0). Body 1.
SceneDescription elasticDropScene(double dropHeight);

}  // namespace physdbg
