#include "scenes/stacking_scenes.h"

#include "engine/colliders/box_collider.h"
#include "scenes/stability_scenes.h"

namespace physdbg {
namespace {

BodyDefinition floorSlab(const Vec3& center, double halfWidth) {
  BodyDefinition floor;
  floor.collider = std::make_shared<BoxCollider>(Vec3(halfWidth, 0.5, halfWidth));
  floor.position = center - Vec3(0, 0.5, 0);
  floor.isStatic = true;
  return floor;
}

}  // namespace

SceneDescription stackScene(int count) {
  SceneDescription scene;
  scene.name = "stack";
  scene.description = std::to_string(count) + " unit boxes stacked on a floor";
  scene.steps = 600;
  scene.layers = "shapes,contacts,overlay";
  scene.bodies.push_back(floorSlab(Vec3::Zero(), 5));
  const auto box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  for (int i = 0; i < count; ++i) {
    BodyDefinition body;
    body.collider = box;
    body.position = Vec3(0, 0.5 + i, 0);
    scene.bodies.push_back(body);
  }
  return scene;
}

SceneDescription pyramidScene(int base, const Vec3& origin) {
  SceneDescription scene;
  scene.name = "pyramid";
  scene.description = "pyramid of unit boxes, " + std::to_string(base) + " at the base, one deep";
  scene.steps = 600;
  scene.layers = "shapes,overlay";
  scene.bodies.push_back(floorSlab(origin, base + 10.0));
  const auto box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  for (int row = 0; row < base; ++row) {
    for (int column = 0; column < base - row; ++column) {
      BodyDefinition body;
      body.collider = box;
      body.position = origin + Vec3(-0.5 * (base - row - 1) + column, 0.5 + row, 0);
      scene.bodies.push_back(body);
    }
  }
  return scene;
}

std::vector<BuiltinScene> stackingScenes() {
  return {
      {"stack", "10 unit boxes stacked on a floor", [] { return stackScene(10); }},
      {"pyramid", "pyramid of 210 unit boxes (20 at the base)", [] { return pyramidScene(20); }},
      {"mass_stack", "6 unit boxes alternating 0.1 kg and 10 kg (the solver stiffens the loaded contacts)",
       [] {
         SceneDescription scene = massStackScene({0.1, 10.0, 0.1, 10.0, 0.1, 10.0});
         scene.name = "mass_stack";
         return scene;
       }},
  };
}

}  // namespace physdbg
