#pragma once
// Wires a scene's collision device to the world: for "gpu", a compute
// context of the chosen backend and the gpu/ stage on it.
#include <memory>

#include "engine/collision_offload.h"
#include "render/renderer.h"
#include "scenes/scene.h"

namespace physdbg::cli {

// Null for a cpu scene. For a gpu scene, the stage on a fresh context; a
// context without compute shaders is a UsageError (exit 2) saying what it lacks.
std::shared_ptr<CollisionOffload> collisionOffloadFor(const SceneDescription& scene, render::Backend backend);

}  // namespace physdbg::cli
