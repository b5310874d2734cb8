// Built-in scenes, generated in code so their sizes can be parameters.
#include <cmath>
#include <filesystem>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "scenes/body_builders.h"
#include "scenes/design_scenes.h"
#include "scenes/scene.h"
#include "scenes/stacking_scenes.h"

namespace physdbg {
namespace {

// A few boxes and spheres tumbling onto a ground slab: the first thing a new
// user renders, so every common shape and a static body appear.
SceneDescription defaultScene() {
  SceneDescription scene;
  scene.name = "default";
  scene.description = "boxes and spheres tumbling onto a ground slab";
  scene.steps = 180;
  scene.bodies.push_back(staticBox(Vec3(0, -0.5, 0), Vec3(6, 0.5, 6)));
  const std::shared_ptr<const Collider> box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  const std::shared_ptr<const Collider> plank = std::make_shared<BoxCollider>(Vec3(0.9, 0.2, 0.4));
  const std::shared_ptr<const Collider> sphere = std::make_shared<SphereCollider>(0.5);
  int index = 0;
  for (int layer = 0; layer < 2; ++layer) {
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column, ++index) {
        const Vec3 position(-2.2 + 2.2 * column, 2.0 + 2.5 * layer + 0.4 * row, -2.2 + 2.2 * row);
        const std::shared_ptr<const Collider> shape = index % 3 == 0 ? sphere : (index % 3 == 1 ? box : plank);
        BodyDefinition body = dynamicBody(shape, position);
        body.orientation = Quat(Eigen::AngleAxisd(0.3 * index, Vec3(1, 2, 0.5).normalized()));
        body.angularVelocity = Vec3(0.5 * std::sin(index), 1.0, 0.4 * std::cos(index));
        body.material.restitution = 0.3;
        scene.bodies.push_back(body);
      }
    }
  }
  return scene;
}

}  // namespace

const std::vector<BuiltinScene>& builtinScenes() {
  static const std::vector<BuiltinScene> scenes = [] {
    std::vector<BuiltinScene> all = {{"default", "boxes and spheres tumbling onto a ground slab", defaultScene}};
    for (BuiltinScene& scene : designScenes()) all.push_back(std::move(scene));
    for (BuiltinScene& scene : stackingScenes()) all.push_back(std::move(scene));
    return all;
  }();
  return scenes;
}

SceneDescription resolveScene(const std::string& nameOrPath) {
  for (const BuiltinScene& scene : builtinScenes()) {
    if (scene.name != nameOrPath) continue;
    SceneDescription made = scene.make();
    made.source = "built-in scene " + scene.name;
    return made;
  }
  if (!std::filesystem::exists(nameOrPath)) {
    std::string names;
    for (const BuiltinScene& scene : builtinScenes()) names += (names.empty() ? "" : ", ") + scene.name;
    throw SceneError(nameOrPath + ": no such built-in scene or scene file (built-in: " + names + ")");
  }
  return loadSceneFile(nameOrPath);
}

}  // namespace physdbg
