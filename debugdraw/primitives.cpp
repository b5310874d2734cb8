#include "debugdraw/primitives.h"

#include <sstream>
#include <stdexcept>

namespace physdbg::debugdraw {

namespace {

std::string validLayerNames() {
  std::string valid;
  for (const auto& entry : allLayers()) valid += (valid.empty() ? "" : ", ") + entry.first;
  return valid;
}

}  // namespace

const std::vector<std::pair<std::string, Layer>>& allLayers() {
  static const std::vector<std::pair<std::string, Layer>> layers = {
      {"shapes", Layer::Shapes}, {"wire", Layer::Wire},         {"aabbs", Layer::Aabbs},
      {"fat", Layer::Fat},       {"tree", Layer::Tree},         {"contacts", Layer::Contacts},
      {"velocities", Layer::Velocities}, {"sleep", Layer::Sleep}, {"pairs", Layer::Pairs},
      {"overlay", Layer::Overlay}};
  return layers;
}

namespace {

// Lists come from command lines and scene files: quote at most a short piece.
std::string shortened(const std::string& text) {
  constexpr std::size_t limit = 48;
  return text.size() <= limit ? text : text.substr(0, limit) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace

LayerSet parseLayers(const std::string& list) {
  LayerSet set;
  std::stringstream stream(list);
  std::string name;
  while (std::getline(stream, name, ',')) {
    if (name.empty()) continue;
    bool found = false;
    for (const auto& [known, layer] : allLayers()) {
      if (known == name) {
        set.add(layer);
        found = true;
      }
    }
    if (!found) throw std::invalid_argument("unknown layer '" + shortened(name) + "' (valid: " + validLayerNames() + ")");
  }
  if (set.empty()) throw std::invalid_argument("no layer given in '" + shortened(list) + "' (valid: " + validLayerNames() + ")");
  return set;
}

std::string layerNames(LayerSet set) {
  std::string names;
  for (const auto& [name, layer] : allLayers()) {
    if (set.has(layer)) names += (names.empty() ? "" : ",") + name;
  }
  return names;
}

void Frame::clear() { *this = Frame{}; }

bool Frame::empty() const { return primitiveCount() == 0; }

std::size_t Frame::primitiveCount() const {
  return boxes.size() + spheres.size() + capsules.size() + meshes.size() + wireBoxes.size() + lines.size() +
         points.size() + arrows.size() + texts.size();
}

}  // namespace physdbg::debugdraw
