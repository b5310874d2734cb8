#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "scenes/scene.h"

namespace physdbg::cli {

int runScenes(const std::vector<std::string>& args) {
  const CommandSpec spec{"scenes", "", "Lists the built-in scenes. Any command taking SCENE accepts these names or a "
                                       "path to a JSON scene file (format: scenes/README.md).", {}, 0, 0};
  if (!Arguments::parse(spec, args)) return 0;
  std::size_t width = 0;
  for (const BuiltinScene& scene : builtinScenes()) width = std::max(width, scene.name.size());
  for (const BuiltinScene& scene : builtinScenes()) {
    std::string name = scene.name;
    name.resize(width + 2, ' ');
    std::cout << name << scene.description << "\n";
  }
  return 0;
}

}  // namespace physdbg::cli
