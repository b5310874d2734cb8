#include "scenes/body_builders.h"

#include "engine/colliders/box_collider.h"

namespace physdbg {

BodyDefinition staticBox(const Vec3& center, const Vec3& halfExtents, const Quat& orientation) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(halfExtents);
  body.position = center;
  body.orientation = orientation;
  body.isStatic = true;
  return body;
}

BodyDefinition dynamicBody(std::shared_ptr<const Collider> collider, const Vec3& position, double mass) {
  BodyDefinition body;
  body.collider = std::move(collider);
  body.position = position;
  body.mass = mass;
  return body;
}

}  // namespace physdbg
