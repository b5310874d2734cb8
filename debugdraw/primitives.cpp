#include "debugdraw/primitives.h"

#include <algorithm>
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
      {"overlay", Layer::Overlay}, {"impulses", Layer::Impulses}, {"grid", Layer::Grid},
      {"mesh", Layer::Mesh}};
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
         points.size() + arrows.size() + texts.size() + labels.size();
}

namespace {

// Calls visit(list) on each primitive list in a fixed order.
template <typename FrameType, typename Visit>
void forEachList(FrameType& frame, Visit visit) {
  visit(frame.boxes);
  visit(frame.spheres);
  visit(frame.capsules);
  visit(frame.meshes);
  visit(frame.wireBoxes);
  visit(frame.lines);
  visit(frame.points);
  visit(frame.arrows);
  visit(frame.texts);
  visit(frame.labels);
}

void fill(Tag& target, const Tag& tag) {
  if (target.layer == 0) target.layer = tag.layer;
  if (target.body < 0) target.body = tag.body;
  if (target.otherBody < 0) target.otherBody = tag.otherBody;
  if (target.node < 0) target.node = tag.node;
  if (target.parent < 0) target.parent = tag.parent;
  if (target.depth < 0) target.depth = tag.depth;
}

}  // namespace

FrameMark markOf(const Frame& frame) {
  FrameMark mark;
  std::size_t list = 0;
  forEachList(frame, [&](const auto& items) { mark.sizes[list++] = items.size(); });
  return mark;
}

void fillTagsSince(Frame& frame, const FrameMark& mark, const Tag& tag) {
  std::size_t list = 0;
  forEachList(frame, [&](auto& items) {
    for (std::size_t i = std::min(mark.sizes[list], items.size()); i < items.size(); ++i) fill(items[i].tag, tag);
    ++list;
  });
}

}  // namespace physdbg::debugdraw
