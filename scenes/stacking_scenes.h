#pragma once
// Scenes that only a stable contact solver survives: stacks, pyramids, mass
// ratios. Used as built-in scenes, in tests and in benchmarks.
#include "scenes/scene.h"

namespace physdbg {

// `count` unit boxes stacked on a static floor, each resting on the one below.
SceneDescription stackScene(int count);
// A pyramid one box deep with `base` unit boxes at the bottom, on a wide floor.
SceneDescription pyramidScene(int base, const Vec3& origin = Vec3::Zero());

// Jolt's PerformanceTest pyramid (Samples/PerformanceTest/PyramidScene.h),
// as Jolt defines it: 15 layers of 2 m boxes (8000 kg: Jolt's default
// density, 1000 kg/m^3), 0.5 m apart between layers, layer i a square of
// 15 - i boxes a side, every other layer offset by half a box; a 100 m floor
// slab whose top is y = 0; Jolt's default material (friction 0.2, no
// restitution); sleeping off, 500 steps of 1/60 s. 1240 boxes.
// scenes/jolt_pyramid.json is the same scene as a file.
SceneDescription joltPyramidScene();

std::vector<BuiltinScene> stackingScenes();

}  // namespace physdbg
