#include "debugdraw/frame_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace physdbg::debugdraw {
namespace {

// The renderer's background: faded primitives are mixed towards it, so the
// picture keeps the scene's shape while the focus stands out. Mixing colours
// rather than lowering alpha keeps solids opaque (no sorting needed).
constexpr Color kBackground{0.11f, 0.12f, 0.14f, 1.0f};
constexpr float kFadedShare = 0.25f;  // of the original colour left

Color faded(Color color) {
  const auto mix = [](float value, float background) { return value * kFadedShare + background * (1 - kFadedShare); };
  return {mix(color.r, kBackground.r), mix(color.g, kBackground.g), mix(color.b, kBackground.b), color.a};
}

bool isLayer(const Tag& tag, Layer layer) { return tag.layer == static_cast<std::uint32_t>(layer); }

enum class Shown { Hidden, Faded, Plain, Focus };

// Everything a decision about one primitive needs, computed once per frame.
struct Focus {
  const ViewSelection& selection;
  std::set<int> bodies;     // highlighted
  std::set<int> treePath;   // tree nodes from the highlighted leaves to the root
  // Sleep with shapes: sleeping bodies' solids darkened instead of outlined.
  std::set<int> darkened;
  bool active() const { return !bodies.empty(); }
  bool touches(const Tag& tag) const { return bodies.count(tag.body) > 0 || bodies.count(tag.otherBody) > 0; }
};

bool layerShown(const Tag& tag, const ViewSelection& selection) {
  if (!selection.layers.has(static_cast<Layer>(tag.layer))) return false;
  if (isLayer(tag, Layer::Tree) && tag.depth >= 0)
    return tag.depth >= selection.treeMinDepth && tag.depth <= selection.treeMaxDepth;
  return true;
}

// Layers whose primitives about a highlighted body show even when not asked
// for: what touches the body, what the broad phase paired it with, and where
// it sits in the tree.
bool aboutRelations(const Tag& tag) {
  return isLayer(tag, Layer::Contacts) || isLayer(tag, Layer::Pairs) || isLayer(tag, Layer::Fat);
}

// A sleeping body's own outline (sleep layer, tagged with the body) gives way
// to its darkened solid when shapes show; island outlines stay.
bool outlineOfDarkenedBody(const Tag& tag, const Focus& focus) {
  return isLayer(tag, Layer::Sleep) && tag.body >= 0 && focus.darkened.count(tag.body) > 0;
}

Shown decide(const Tag& tag, bool text, const Focus& focus) {
  const bool shown = layerShown(tag, focus.selection) && !outlineOfDarkenedBody(tag, focus);
  if (!focus.active() || text || isLayer(tag, Layer::Overlay) || isLayer(tag, Layer::Grid))
    return shown ? Shown::Plain : Shown::Hidden;
  if (isLayer(tag, Layer::Tree)) {
    if (focus.treePath.count(tag.node) > 0) return Shown::Focus;
    return shown ? Shown::Faded : Shown::Hidden;
  }
  if (focus.touches(tag) && (shown || aboutRelations(tag))) return Shown::Plain;
  return shown ? Shown::Faded : Shown::Hidden;
}

constexpr float kSleepingShade = 0.35f;

Color shaded(Color color, float factor) { return {color.r * factor, color.g * factor, color.b * factor, color.a}; }

template <typename Item>
void copySelected(const std::vector<Item>& from, std::vector<Item>& to, const Focus& focus, bool text = false) {
  for (const Item& item : from) {
    const Shown shown = decide(item.tag, text, focus);
    if (shown == Shown::Hidden) continue;
    to.push_back(item);
    if (isLayer(item.tag, Layer::Shapes) && focus.darkened.count(item.tag.body) > 0)
      to.back().color = shaded(item.color, kSleepingShade);
    if (shown == Shown::Faded) to.back().color = faded(item.color);
    if (shown == Shown::Focus) to.back().color = focusColor;
  }
}

template <typename Item>
void requireTags(const std::vector<Item>& items, const char* list) {
  for (const Item& item : items) {
    if (item.tag.layer == 0)
      throw std::invalid_argument(std::string("the frame's ") + list +
                                  " carry no layer tags (a version 1 recording?): layers and bodies cannot be chosen");
  }
}

void requireAllTagged(const Frame& frame) {
  requireTags(frame.boxes, "boxes");
  requireTags(frame.spheres, "spheres");
  requireTags(frame.capsules, "capsules");
  requireTags(frame.meshes, "meshes");
  requireTags(frame.wireBoxes, "wire boxes");
  requireTags(frame.lines, "lines");
  requireTags(frame.points, "points");
  requireTags(frame.arrows, "arrows");
  requireTags(frame.texts, "texts");
  requireTags(frame.labels, "labels");
}

const BodyInfo* findBody(const Frame& frame, int index) {
  for (const BodyInfo& body : frame.bodies)
    if (body.index == index) return &body;
  return nullptr;
}

const BodyInfo& requireBody(const Frame& frame, int index, const char* purpose) {
  if (const BodyInfo* body = findBody(frame, index)) return *body;
  throw std::invalid_argument(std::string(purpose) + ": the frame has no body " + std::to_string(index) + " (it has " +
                              std::to_string(frame.bodies.size()) + ")");
}

// Parent links from the tree layer's node tags; walks from each highlighted
// leaf's parent to the root. A cycle (a corrupt recording) stops the walk.
std::set<int> treePathOf(const Frame& frame, const std::set<int>& bodies) {
  std::map<int, int> parentOf;
  for (const WireBox& box : frame.wireBoxes)
    if (isLayer(box.tag, Layer::Tree) && box.tag.node >= 0) parentOf[box.tag.node] = box.tag.parent;
  std::set<int> path;
  for (int index : bodies) {
    const BodyInfo* body = findBody(frame, index);
    int node = body ? body->treeParent : -1;
    while (node >= 0 && path.insert(node).second) {
      const auto parent = parentOf.find(node);
      node = parent == parentOf.end() ? -1 : parent->second;
    }
  }
  return path;
}

Vec3 centreOf(const BodyInfo& body) { return 0.5 * (body.boundsMin + body.boundsMax); }

// A box a little larger than the body's bounds, in the focus colour.
void addHighlightBoxes(const Frame& tagged, const Focus& focus, Frame& out) {
  for (int index : focus.bodies) {
    const BodyInfo& body = requireBody(tagged, index, "--highlight");
    if (body.absent) continue;  // its body lines say so
    const Vec3 half = 0.5 * (body.boundsMax - body.boundsMin);
    out.wireBoxes.push_back({centreOf(body), Quat::Identity(), half * 1.04 + Vec3::Constant(1e-3 * half.norm()),
                             focusColor});
  }
}

// Corner brackets around the followed body: the view moves with it, so
// without a mark nothing says which body the camera is on.
void addFollowMarker(const BodyInfo& body, Frame& out) {
  const Vec3 low = body.boundsMin, high = body.boundsMax;
  const Vec3 arm = 0.3 * (high - low);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 sign((corner & 1) ? -1.0 : 1.0, (corner & 2) ? -1.0 : 1.0, (corner & 4) ? -1.0 : 1.0);
    const Vec3 at((corner & 1) ? high.x() : low.x(), (corner & 2) ? high.y() : low.y(), (corner & 4) ? high.z() : low.z());
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 end = at;
      end[axis] += sign[axis] * arm[axis];
      out.lines.push_back({at, end, followColor});
    }
  }
}

std::size_t textCharacters(const Frame& frame) {
  std::size_t count = 0;
  for (const Text& text : frame.texts) count += text.text.size();
  for (const Label& label : frame.labels) count += label.text.size();
  return count;
}

// Highlighted bodies first, then the followed one, then every body by index,
// while the frame's text budget lasts.
int addLabels(const Frame& tagged, const ViewSelection& selection, Frame& out) {
  std::vector<const BodyInfo*> order;
  std::set<int> placed;
  const auto enqueue = [&](const BodyInfo* body) {
    if (body && !body->absent && placed.insert(body->index).second) order.push_back(body);
  };
  for (int index : selection.highlight) enqueue(findBody(tagged, index));
  if (selection.follow) enqueue(findBody(tagged, *selection.follow));
  for (const BodyInfo& body : tagged.bodies) enqueue(&body);
  std::size_t budget = maxFrameTextCharacters - std::min(maxFrameTextCharacters, textCharacters(out));
  int leftOut = 0;
  const std::set<int> highlighted(selection.highlight.begin(), selection.highlight.end());
  for (const BodyInfo* body : order) {
    std::string text = std::to_string(body->index);
    if (!body->name.empty()) text.append(" ").append(body->name, 0, 64);
    if (text.size() > budget || !centreOf(*body).allFinite()) {
      ++leftOut;
      continue;
    }
    budget -= text.size();
    const Color color = highlighted.count(body->index) ? focusColor : Color{1, 1, 1, 1};
    out.labels.push_back({centreOf(*body), 1.0f, text, color, Tag{}, true});
  }
  return leftOut;
}

std::string vectorText(const Vec3& v) {
  char text[96];
  // What rounds to zero prints as 0.00: "-0.00" would read as a direction.
  const auto shown = [](double value) { return std::abs(value) < 0.005 ? 0.0 : value; };
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", shown(v.x()), shown(v.y()), shown(v.z()));
  return text;
}

// Two lines per highlighted body at the bottom left: which body, its contact
// points in the frame and whether it sleeps; where it is and how fast.
void addBodyLines(const Frame& tagged, const ViewSelection& selection, Frame& out) {
  const float scale = selection.imageWidth >= 800 ? 2.0f : 1.0f;
  const float lineHeight = 12 * scale;
  float y = static_cast<float>(selection.imageHeight) - 6 * scale - 2 * lineHeight * selection.highlight.size();
  for (int index : selection.highlight) {
    const BodyInfo& body = requireBody(tagged, index, "--highlight");
    std::string name = "body " + std::to_string(body.index);
    if (!body.name.empty()) name.append(" '").append(body.name, 0, 48).append("'");
    name += "  contacts " + std::to_string(body.contacts);
    if (body.absent) name += "  absent";
    if (body.asleep) name += "  asleep";
    if (body.isStatic) name += "  static";
    const std::string state = "  p " + vectorText(body.position) + " m  v " + vectorText(body.linearVelocity) + " m/s";
    for (const std::string& line : {name, state}) {
      out.texts.push_back({6 * scale, std::max(y, 0.0f), scale, line, focusColor});
      y += lineHeight;
    }
  }
}

// Legends (the tree's depths, the impulse scale) are stacked top left under
// the overlay in the order drawn, after the selection: a depth range or a
// hidden layer leaves no gap, and two legends never overlap.
void stackLegends(Frame& out) {
  constexpr float top = 64, lineHeight = 11;
  float y = top;
  for (Text& text : out.texts) {
    if (!isLayer(text.tag, Layer::Tree) && !isLayer(text.tag, Layer::Impulses)) continue;
    text.y = y;
    y += lineHeight * text.scale;
  }
}

}  // namespace

LayerSet layersNeeded(const ViewSelection& selection) {
  LayerSet layers = selection.layers;
  if (!selection.highlight.empty()) {
    for (Layer layer : {Layer::Contacts, Layer::Pairs, Layer::Tree, Layer::Fat}) layers.add(layer);
  }
  return layers;
}

Frame selectView(const Frame& tagged, const ViewSelection& selection, ViewReport* report) {
  requireAllTagged(tagged);
  Focus focus{selection, {selection.highlight.begin(), selection.highlight.end()}, {}};
  for (int index : focus.bodies) requireBody(tagged, index, "--highlight");
  focus.treePath = treePathOf(tagged, focus.bodies);
  if (selection.layers.has(Layer::Sleep) && selection.layers.has(Layer::Shapes)) {
    for (const BodyInfo& body : tagged.bodies)
      if (body.asleep) focus.darkened.insert(body.index);
  }
  Frame out;
  copySelected(tagged.boxes, out.boxes, focus);
  copySelected(tagged.spheres, out.spheres, focus);
  copySelected(tagged.capsules, out.capsules, focus);
  copySelected(tagged.meshes, out.meshes, focus);
  copySelected(tagged.wireBoxes, out.wireBoxes, focus);
  copySelected(tagged.lines, out.lines, focus);
  copySelected(tagged.points, out.points, focus);
  copySelected(tagged.arrows, out.arrows, focus);
  copySelected(tagged.texts, out.texts, focus, true);
  copySelected(tagged.labels, out.labels, focus, true);
  out.bodies = tagged.bodies;
  stackLegends(out);
  if (focus.active()) addHighlightBoxes(tagged, focus, out);
  if (selection.follow) {
    const BodyInfo& followed = requireBody(tagged, *selection.follow, "--follow");
    if (!followed.absent) addFollowMarker(followed, out);
  }
  if (focus.active() && selection.layers.has(Layer::Overlay)) addBodyLines(tagged, selection, out);
  const int leftOut = selection.labels ? addLabels(tagged, selection, out) : 0;
  if (report) report->labelsLeftOut = leftOut;
  return out;
}

std::vector<int> contactPartners(const Frame& tagged, int body) {
  std::set<int> partners;
  const auto visit = [&](const Tag& tag) {
    if (!isLayer(tag, Layer::Contacts) && !isLayer(tag, Layer::Impulses)) return;
    if (tag.body == body && tag.otherBody >= 0) partners.insert(tag.otherBody);
    if (tag.otherBody == body && tag.body >= 0) partners.insert(tag.body);
  };
  for (const Point& point : tagged.points) visit(point.tag);
  for (const Arrow& arrow : tagged.arrows) visit(arrow.tag);
  return {partners.begin(), partners.end()};
}

}  // namespace physdbg::debugdraw
