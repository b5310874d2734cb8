#pragma once
// Small builders for the bodies scenes are made of, shared by the built-in
// scenes, the stability suite and the benchmarks.
#include <memory>

#include "engine/dynamics/rigid_body.h"

namespace physdbg {

BodyDefinition staticBox(const Vec3& center, const Vec3& halfExtents, const Quat& orientation = Quat::Identity());
BodyDefinition dynamicBody(std::shared_ptr<const Collider> collider, const Vec3& position, double mass = 1.0);

}  // namespace physdbg
