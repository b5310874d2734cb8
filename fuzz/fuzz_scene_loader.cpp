// Fuzz target: a scene file from a stranger. Parsing and building must either
// succeed or throw SceneError; a small scene that loads is also stepped, so
// whatever the loader lets through must not crash the engine either.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/world.h"
#include "scenes/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    physdbg::SceneDescription scene = physdbg::parseScene(text, "fuzz.json");
    if (scene.bodies.size() > 64) return 0;  // stepping big grids proves nothing new and is slow
    physdbg::World world = physdbg::buildWorld(scene);
    for (int step = 0; step < 8; ++step) world.step();
  } catch (const physdbg::SceneError&) {
  }
  return 0;
}
