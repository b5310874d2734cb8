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

SceneDescription joltPyramidScene() {
  constexpr int height = 15;
  constexpr double size = 2.0, separation = 0.5, half = 0.5 * size;
  SceneDescription scene;
  scene.name = "jolt_pyramid";
  scene.description = "Jolt's PerformanceTest pyramid: 1240 boxes of 2 m in 15 layers, sleeping off";
  scene.steps = 500;
  scene.layers = "shapes,overlay";
  scene.world.allowSleep = false;
  BodyDefinition floor;
  floor.collider = std::make_shared<BoxCollider>(Vec3(50, 1, 50));
  floor.position = Vec3(0, -1, 0);
  floor.isStatic = true;
  floor.material = {0.0, 0.2, 0.2};
  scene.bodies.push_back(floor);
  const auto box = std::make_shared<BoxCollider>(Vec3::Constant(half));
  for (int i = 0; i < height; ++i) {
    const double shift = (i & 1) ? half : 0.0;
    // x fastest, then z, as a scene file's `repeat` lists its copies.
    for (int k = i / 2; k < height - (i + 1) / 2; ++k)
      for (int j = i / 2; j < height - (i + 1) / 2; ++j) {
        BodyDefinition body;
        body.collider = box;
        body.mass = 1000.0 * size * size * size;
        body.material = {0.0, 0.2, 0.2};
        body.position = Vec3(-height + size * j + shift, 1.0 + (size + separation) * i, -height + size * k + shift);
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
