#include "scenes/stability_scenes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {
namespace {

const Vec3 unitHalfExtents(0.5, 0.5, 0.5);

SceneDescription quietScene(const std::string& name, const std::string& description, int steps) {
  SceneDescription scene;
  scene.name = name;
  scene.description = description;
  scene.steps = steps;
  scene.world.allowSleep = false;
  scene.layers = "shapes,contacts,overlay";
  return scene;
}

BodyDefinition boxBody(const Vec3& halfExtents, const Vec3& position, const Quat& orientation = Quat::Identity()) {
  BodyDefinition body;
  body.collider = std::make_shared<BoxCollider>(halfExtents);
  body.position = position;
  body.orientation = orientation;
  return body;
}

BodyDefinition staticSlab(const Vec3& center, const Vec3& halfExtents, const Quat& orientation = Quat::Identity()) {
  BodyDefinition slab = boxBody(halfExtents, center, orientation);
  slab.isStatic = true;
  return slab;
}

// A slab whose top face is the plane y = 0.
BodyDefinition floorSlab(double halfWidth) { return staticSlab(Vec3(0, -0.5, 0), Vec3(halfWidth, 0.5, halfWidth)); }

BodyDefinition unitBox(const Vec3& position, double mass = 1.0) {
  BodyDefinition box = boxBody(unitHalfExtents, position);
  box.mass = mass;
  return box;
}

void requireFiniteNonNegative(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) throw std::invalid_argument(std::string(what) + " must be finite and >= 0");
}

}  // namespace

SceneDescription massStackScene(const std::vector<double>& masses) {
  if (masses.empty()) throw std::invalid_argument("massStackScene: at least one mass is needed");
  SceneDescription scene = quietScene("mass_stack", std::to_string(masses.size()) + " unit boxes of mixed mass", 600);
  scene.bodies.push_back(floorSlab(5.0));
  for (std::size_t i = 0; i < masses.size(); ++i) {
    if (!std::isfinite(masses[i]) || !(masses[i] > 0.0))
      throw std::invalid_argument("massStackScene: mass " + std::to_string(i) + " must be positive and finite");
    scene.bodies.push_back(unitBox(Vec3(0, 0.5 + static_cast<double>(i), 0), masses[i]));
  }
  return scene;
}

SceneDescription slidingBlockScene(double speed, double dynamicFriction, double staticFriction) {
  requireFiniteNonNegative(speed, "slidingBlockScene: speed");
  requireFiniteNonNegative(dynamicFriction, "slidingBlockScene: dynamic friction");
  requireFiniteNonNegative(staticFriction, "slidingBlockScene: static friction");
  SceneDescription scene = quietScene("sliding_block", "a unit box sliding to a stop on flat ground", 300);
  const Material material{0.0, staticFriction, dynamicFriction};
  BodyDefinition floor = staticSlab(Vec3(20.0, -0.5, 0), Vec3(40.0, 0.5, 5.0));
  floor.material = material;
  BodyDefinition block = unitBox(Vec3(0, 0.5, 0));
  block.linearVelocity = Vec3(speed, 0, 0);
  block.material = material;
  scene.bodies = {floor, block};
  return scene;
}

Vec3 slopeDownhill(double angle) { return Vec3(-std::cos(angle), -std::sin(angle), 0); }

SceneDescription slopeScene(double angle, double friction) {
  if (!(angle > 0.0 && angle < 0.5 * std::numbers::pi))
    throw std::invalid_argument("slopeScene: angle must lie in (0, pi/2) radians");
  requireFiniteNonNegative(friction, "slopeScene: friction");
  SceneDescription scene = quietScene("slope", "a unit box on a slope", 300);
  const Quat tilt(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
  const Vec3 normal = tilt * Vec3::UnitY();
  const Material material{0.0, friction, friction};
  BodyDefinition slope = staticSlab(Vec3::Zero(), Vec3(10.0, 0.5, 3.0), tilt);
  slope.material = material;
  BodyDefinition block = unitBox(normal);  // slab half thickness + block half size
  block.orientation = tilt;
  block.material = material;
  scene.bodies = {slope, block};
  return scene;
}

SceneDescription bulletScene(double speed, BulletShape shape) {
  requireFiniteNonNegative(speed, "bulletScene: speed");
  SceneDescription scene = quietScene("bullet", "a small fast body fired at a thin wall", 120);
  scene.world.gravity = Vec3::Zero();
  BodyDefinition bullet;
  if (shape == BulletShape::Sphere)
    bullet.collider = std::make_shared<SphereCollider>(bulletSize);
  else
    bullet.collider = std::make_shared<BoxCollider>(Vec3::Constant(bulletSize));
  bullet.position = Vec3(-5.0, 0, 0);
  bullet.linearVelocity = Vec3(speed, 0, 0);
  bullet.mass = 0.01;
  scene.bodies = {staticSlab(Vec3::Zero(), Vec3(wallHalfThickness, 2.0, 2.0)), bullet};
  return scene;
}

SceneDescription tumblingBoxScene() {
  SceneDescription scene = quietScene("tumbling_box", "a free box spinning at (1, 2, 3) rad/s", 500);
  scene.world.gravity = Vec3::Zero();
  scene.world.dt = 0.01;
  BodyDefinition box = boxBody(Vec3(0.1, 0.2, 0.3), Vec3::Zero());
  box.angularVelocity = Vec3(1, 2, 3);
  scene.bodies = {box};
  return scene;
}

SceneDescription overlappingBoxesScene(double overlapFraction) {
  if (!(overlapFraction >= 0.0 && overlapFraction < 1.0))
    throw std::invalid_argument("overlappingBoxesScene: overlap fraction must lie in [0, 1)");
  SceneDescription scene = quietScene("overlap", "a unit box sunk into another", 120);
  scene.bodies = {floorSlab(5.0), unitBox(Vec3(0, 0.5, 0)), unitBox(Vec3(0, 1.5 - overlapFraction, 0))};
  return scene;
}

SceneDescription elasticDropScene(double dropHeight) {
  requireFiniteNonNegative(dropHeight, "elasticDropScene: drop height");
  SceneDescription scene = quietScene("elastic_drop", "a sphere with restitution 1 bouncing on the floor", 600);
  BodyDefinition ball;
  ball.collider = std::make_shared<SphereCollider>(0.5);
  ball.position = Vec3(0, dropHeight + 0.5, 0);
  ball.material.restitution = 1.0;
  scene.bodies = {floorSlab(5.0), ball};
  return scene;
}

}  // namespace physdbg
