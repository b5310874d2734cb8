// Turns the world's state into debug-draw primitives, one function per layer.
// Only the requested layers are computed.
#include <cmath>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"

namespace physdbg {
namespace {

namespace dd = debugdraw;

// Distinct, deterministic body colours: hues spaced by the golden angle.
dd::Color bodyColor(std::size_t index) {
  const double hue = std::fmod(0.08 + 0.618033988749895 * static_cast<double>(index), 1.0) * 6.0;
  const double saturation = 0.55, value = 0.92;
  const int sector = static_cast<int>(hue) % 6;
  const double fraction = hue - std::floor(hue);
  const double p = value * (1 - saturation), q = value * (1 - saturation * fraction),
               t = value * (1 - saturation * (1 - fraction));
  double r = value, g = t, b = p;
  switch (sector) {
    case 1: r = q; g = value; b = p; break;
    case 2: r = p; g = value; b = t; break;
    case 3: r = p; g = q; b = value; break;
    case 4: r = t; g = p; b = value; break;
    case 5: r = value; g = p; b = q; break;
    default: break;
  }
  return {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f};
}

void emitShape(const RigidBody& body, dd::Color color, dd::Frame& frame) {
  const Collider& collider = body.collider();
  switch (collider.kind()) {
    case ColliderKind::Sphere:
      frame.spheres.push_back({body.position(), body.orientation(),
                               static_cast<const SphereCollider&>(collider).radius(), color});
      break;
    case ColliderKind::Box:
      frame.boxes.push_back({body.position(), body.orientation(),
                             static_cast<const BoxCollider&>(collider).halfExtents(), color});
      break;
    default: {
      // Shapes without a dedicated primitive are drawn as their local box.
      const Aabb local = collider.localBounds();
      frame.boxes.push_back({body.transform().apply(local.center()), body.orientation(), local.halfExtents(), color});
      break;
    }
  }
}

void emitWire(const RigidBody& body, dd::Frame& frame) {
  const Aabb local = body.collider().localBounds();
  frame.wireBoxes.push_back({body.transform().apply(local.center()), body.orientation(), local.halfExtents(),
                             {0.95f, 0.95f, 0.95f, 1.0f}});
}

}  // namespace

void World::emitDebugDraw(dd::LayerSet layers, dd::Frame& frame) const {
  if (layers.empty()) return;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const RigidBody& body = bodies_[i];
    if (!body.hasFiniteState()) continue;
    if (layers.has(dd::Layer::Shapes)) emitShape(body, body.isStatic() ? dd::colors::staticBody : bodyColor(i), frame);
    if (layers.has(dd::Layer::Wire)) emitWire(body, frame);
    if (layers.has(dd::Layer::Aabbs)) {
      const Aabb box = body.collider().worldBounds(body.transform());
      frame.wireBoxes.push_back({box.center(), Quat::Identity(), box.halfExtents(), dd::colors::tightBox});
    }
  }
}

}  // namespace physdbg
