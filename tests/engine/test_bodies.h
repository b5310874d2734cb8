#pragma once
// The bodies the world tests build their scenes from: a 20 m floor slab whose
// top is y = 0, unit boxes and balls of radius 0.5 with default materials.
#include <memory>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/dynamics/rigid_body.h"

namespace physdbg::testbodies {

inline BodyDefinition floorSlab() {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(Vec3(10, 0.5, 10));
  body.position = Vec3(0, -0.5, 0);
  body.isStatic = true;
  return body;
}

inline BodyDefinition box(const Vec3& position, double halfSide = 0.5) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(Vec3::Constant(halfSide));
  body.position = position;
  return body;
}

inline BodyDefinition ball(const Vec3& position) {
  BodyDefinition body;
  body.collider = std::make_shared<SphereCollider>(0.5);
  body.position = position;
  return body;
}

}  // namespace physdbg::testbodies
