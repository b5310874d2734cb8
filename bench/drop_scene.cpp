#include "bench/drop_scene.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg::bench {
namespace {

constexpr double kSpacing = 1.2;
constexpr double kWallHalfThickness = 0.5;
constexpr double kJitter = 0.05;  // m, at most, sideways

BodyDefinition wall(const Vec3& center, const Vec3& halfExtents) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(halfExtents);
  body.position = center;
  body.isStatic = true;
  body.material = {0.2, 0.5, 0.5};
  return body;
}

}  // namespace

double dropJitter(std::uint64_t k) {
  std::uint64_t z = k + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return 2.0 * static_cast<double>(z >> 11) * 0x1.0p-53 - 1.0;
}

DropScene dropScene(int count, DropShape shape, bool jittered) {
  if (count < 1) throw std::invalid_argument("dropScene: count must be at least 1");
  const int side = static_cast<int>(std::ceil(std::sqrt(count / 4.0)));
  const int layers = (count + side * side - 1) / (side * side);
  DropScene drop;
  drop.container.innerHalfWidth = 0.5 * side * kSpacing;
  drop.container.wallTop = layers * kSpacing + 2.0;
  SceneDescription& scene = drop.scene;
  scene.name = std::string(shape == DropShape::Sphere ? "drop_spheres" : "drop_boxes") + (jittered ? "" : "_columns");
  scene.description = std::to_string(count) + " bodies dropped into an open container";
  scene.steps = 600;
  scene.world.allowSleep = false;
  const double half = drop.container.innerHalfWidth, outer = half + 2 * kWallHalfThickness;
  const double wallHalfHeight = 0.5 * drop.container.wallTop;
  scene.bodies.push_back(wall(Vec3(0, -0.5, 0), Vec3(outer, 0.5, outer)));
  for (const double sign : {-1.0, 1.0}) {
    const double offset = sign * (half + kWallHalfThickness);
    scene.bodies.push_back(wall(Vec3(offset, wallHalfHeight, 0), Vec3(kWallHalfThickness, wallHalfHeight, outer)));
    scene.bodies.push_back(wall(Vec3(0, wallHalfHeight, offset), Vec3(outer, wallHalfHeight, kWallHalfThickness)));
  }
  std::shared_ptr<const Collider> collider;
  if (shape == DropShape::Sphere) collider = std::make_shared<SphereCollider>(0.5);
  else collider = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  for (int i = 0; i < count; ++i) {
    const int cell = i % (side * side), layer = i / (side * side);
    BodyDefinition body;
    body.collider = collider;
    body.position = Vec3((cell % side - 0.5 * (side - 1)) * kSpacing, 1.0 + layer * kSpacing,
                         (cell / side - 0.5 * (side - 1)) * kSpacing);
    if (jittered) {
      const auto k = static_cast<std::uint64_t>(i);
      body.position += kJitter * Vec3(dropJitter(2 * k), 0.0, dropJitter(2 * k + 1));
    }
    body.material = {0.2, 0.5, 0.5};
    scene.bodies.push_back(body);
  }
  return drop;
}

bool leftContainer(const Vec3& position, const DropContainer& container) {
  const double limit = container.innerHalfWidth + 0.01;
  return std::abs(position.x()) > limit || std::abs(position.z()) > limit || position.y() < -0.01;
}

}  // namespace physdbg::bench
