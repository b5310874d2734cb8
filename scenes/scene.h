#pragma once
// A scene: world settings, bodies and presentation hints, independent of where
// it came from (a JSON file or a built-in generator). The format is documented
// in scenes/README.md.
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/dynamics/rigid_body.h"
#include "engine/dynamics/step_schedule.h"
#include "engine/world_settings.h"

namespace physdbg {

class CollisionOffload;
class World;

// Bad scene input. The message names the file, the key path and the problem.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneCamera {
  std::optional<Vec3> eye;
  std::optional<Vec3> target;
  double fovYDegrees = 45.0;
  bool orthographic = false;
};

struct SceneDescription {
  std::string name;
  // Where the scene came from ("drop.json", "built-in scene stack"), and for
  // each body the JSON entry it was read from (empty for built-in scenes), so
  // errors raised while building the world name the file and the key.
  std::string source;
  std::vector<std::size_t> bodyEntries;
  // The scene's "name" of each body ("" where it gives none; may be shorter
  // than bodies): labels and the highlight overlay show it. A repeated body's
  // copies are "name[0]", "name[1]", ...
  std::vector<std::string> bodyNames;
  std::string description;
  WorldSettings world;
  int steps = 240;
  std::vector<BodyDefinition> bodies;
  std::vector<ScheduledForce> forces;  // body indices are world body ids (after `repeat`)
  std::vector<BodyLifetime> lifetimes;  // bodies added or removed during the run (world ids)
  std::vector<BodyId> sleeping;         // bodies that start asleep ("asleep": true; world ids)
  std::vector<ScheduledState> states;   // "set": state changes during the run (world ids)
  std::optional<SceneCamera> camera;
  std::optional<std::string> layers;  // the scene's default debug layers
  // What the loader did that the file did not say, for the user to read
  // (degenerate mesh triangles dropped): "file: key: what".
  std::vector<std::string> notes;
  // "collision_layers": names of the filter bits, bit k named by entry k.
  std::vector<std::string> collisionLayers;
};

// `sourceName` is used in error messages (usually the file path).
SceneDescription parseScene(const std::string& jsonText, const std::string& sourceName);
SceneDescription loadSceneFile(const std::string& path);

struct BuiltinScene {
  std::string name;
  std::string description;
  std::function<SceneDescription()> make;
};

const std::vector<BuiltinScene>& builtinScenes();

// A built-in scene name, or else a path to a scene file. Throws SceneError.
SceneDescription resolveScene(const std::string& nameOrPath);

// Throws SceneError naming the body when the engine rejects a definition.
// A scene whose collision device is gpu needs `offload` (gpu/gpu_collision.h).
World buildWorld(const SceneDescription& scene, std::shared_ptr<CollisionOffload> offload = nullptr);

}  // namespace physdbg
