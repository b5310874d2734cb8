// A scene's world: the one place in scenes/ that compiles the engine's
// World, so parsing a scene file does not.
#include <optional>
#include <string>

#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {

// Settings and bodies were validated key by key; what the engine still
// rejects is reported against the file and the entry it came from.
World buildWorld(const SceneDescription& scene, std::shared_ptr<CollisionOffload> offload) {
  const std::string source = scene.source.empty() ? "scene " + scene.name : scene.source;
  // Runs `call`; a refusal names the file and what `where()` says.
  const auto named = [&](const auto& where, const auto& call) {
    try {
      call();
    } catch (const std::invalid_argument& error) {
      throw SceneError(source + ": " + where() + ": " + error.what());
    }
  };
  // "bodies[3] (body 17)", or "body 17" for a built-in scene.
  const auto bodyWhere = [&](std::size_t i) {
    if (i >= scene.bodyEntries.size()) return "body " + std::to_string(i);
    return "bodies[" + std::to_string(scene.bodyEntries[i]) + "] (body " + std::to_string(i) + ")";
  };
  const auto entry = [](const char* list, std::size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; };
  std::optional<World> world;
  named([] { return std::string("world settings"); }, [&] { world.emplace(scene.world, std::move(offload)); });
  world->reserveBodies(scene.bodies.size());  // bounded by the loader's body limit
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    named([&] { return bodyWhere(i); }, [&] { world->addBody(scene.bodies[i]); });
  for (const BodyId id : scene.sleeping) named([&] { return bodyWhere(id) + ": asleep"; }, [&] { world->sleep(id); });
  for (std::size_t i = 0; i < scene.forces.size(); ++i)
    named([&] { return entry("forces", i); }, [&] { world->scheduleForce(scene.forces[i]); });
  for (std::size_t i = 0; i < scene.states.size(); ++i)
    named([&] { return entry("set", i); }, [&] { world->scheduleState(scene.states[i]); });
  for (const BodyLifetime& lifetime : scene.lifetimes)
    named([&] { return "body " + std::to_string(lifetime.body); }, [&] { world->scheduleLifetime(lifetime); });
  return std::move(*world);
}

}  // namespace physdbg
