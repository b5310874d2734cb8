#pragma once
// Scenes that only a stable contact solver survives: stacks, pyramids, mass
// ratios. Used as built-in scenes, in tests and in benchmarks.
#include "scenes/scene.h"

namespace physdbg {

// `count` unit boxes stacked on a static floor, each resting on the one below.
SceneDescription stackScene(int count);
// A pyramid one box deep with `base` unit boxes at the bottom, on a wide floor.
SceneDescription pyramidScene(int base, const Vec3& origin = Vec3::Zero());

std::vector<BuiltinScene> stackingScenes();

}  // namespace physdbg
