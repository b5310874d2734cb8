#pragma once
// Debug-draw primitives: the only thing the engine and the renderer share.
// Positions are double so that a scene 1e7 m from the origin still draws
// correctly: the renderer subtracts its camera origin before going to float.
// A Frame is plain data, so it can be recorded, replayed, or compared.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace physdbg::debugdraw {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

struct Color {
  float r = 1, g = 1, b = 1, a = 1;
};

// Colours with a meaning, used by every producer so pictures read the same.
namespace colors {
inline constexpr Color treeNode{0.15f, 0.35f, 1.0f, 1.0f};     // tree AABBs: blue
inline constexpr Color fatBox{0.1f, 0.85f, 0.2f, 1.0f};        // enlarged boxes: green
// The `fat` layer's green, paler and translucent: a thousand overlapping fat
// boxes at full strength merge into one green mass.
inline constexpr Color fatLayer{0.55f, 0.95f, 0.6f, 0.4f};
inline constexpr Color colliding{1.0f, 0.1f, 0.1f, 1.0f};      // collider box in contact: red
inline constexpr Color tightBox{0.85f, 0.85f, 0.85f, 1.0f};    // collider box, no contact
inline constexpr Color contactPoint{1.0f, 0.9f, 0.1f, 1.0f};   // contact points: yellow
inline constexpr Color contactNormal{1.0f, 0.5f, 0.0f, 1.0f};  // contact normals: orange
inline constexpr Color staticBody{0.55f, 0.55f, 0.58f, 1.0f};
inline constexpr Color sensorOverlap{0.2f, 0.95f, 0.95f, 1.0f};  // a sensor overlapping a body: cyan
inline constexpr Color testedTriangle{1.0f, 0.6f, 0.15f, 1.0f};   // mesh layer: a triangle tested this step
inline constexpr Color correctedEdge{1.0f, 0.2f, 0.85f, 1.0f};    // mesh layer: where the face normal replaced an edge's
inline constexpr float sensorAlpha = 0.35f;  // sensors' solids are see-through: they push nothing
}  // namespace colors

// Bit flags naming what a frame should contain. A producer computes nothing
// for a layer that is not requested.
enum class Layer : std::uint32_t {
  Shapes = 1u << 0,
  Wire = 1u << 1,
  Aabbs = 1u << 2,
  Fat = 1u << 3,
  Tree = 1u << 4,
  Contacts = 1u << 5,
  Velocities = 1u << 6,
  Sleep = 1u << 7,
  Pairs = 1u << 8,
  Overlay = 1u << 9,
  Impulses = 1u << 10,
  Grid = 1u << 11,
  Mesh = 1u << 12,  // level geometry's triangles the narrow phase tested, and its corrected edges
};

// Every layer's bit (Shapes .. Mesh).
inline constexpr std::uint32_t allLayerBits = (static_cast<std::uint32_t>(Layer::Mesh) << 1) - 1;

struct LayerSet {
  std::uint32_t bits = 0;
  bool has(Layer layer) const { return (bits & static_cast<std::uint32_t>(layer)) != 0; }
  void add(Layer layer) { bits |= static_cast<std::uint32_t>(layer); }
  bool empty() const { return bits == 0; }
};

// Primitives each layer added, summed over frames: how a caller tells a
// requested layer that drew nothing (no contacts, no tree) from a broken one.
struct LayerCounts {
  std::array<std::size_t, 32> primitives{};  // by the layer's bit number
  void add(Layer layer, std::size_t count) { primitives[bitNumber(layer)] += count; }
  std::size_t of(Layer layer) const { return primitives[bitNumber(layer)]; }

 private:
  static int bitNumber(Layer layer) { return std::countr_zero(static_cast<std::uint32_t>(layer)); }
};

// Parses "shapes,aabbs,..." into a set. Throws std::invalid_argument naming the
// unknown layer, or saying no layer was given ("", ","): asking for no layer
// draws blank frames, which is never what a user meant.
LayerSet parseLayers(const std::string& list);
std::string layerNames(LayerSet set);
const std::vector<std::pair<std::string, Layer>>& allLayers();

// Who drew a primitive and for which body, so a viewer (replay, --highlight,
// --tree-depth) can choose layers and bodies after the run, with no engine.
// Producers fill it; unset fields stay at their defaults.
struct Tag {
  std::uint32_t layer = 0;       // one Layer bit; 0 = untagged (version 1 recordings)
  std::int32_t body = -1;        // the body drawn, or the first body of a pair or contact
  std::int32_t otherBody = -1;   // the second body of a pair or contact
  std::int32_t node = -1;        // broad-phase tree node (tree and fat layers)
  std::int32_t parent = -1;      // that node's parent, -1 at the root
  std::int32_t depth = -1;       // tree depth of the node, or of a tree legend line
  bool operator==(const Tag&) const = default;
};

inline Tag tagOf(Layer layer, int body = -1, int otherBody = -1) {
  Tag tag;
  tag.layer = static_cast<std::uint32_t>(layer);
  tag.body = body;
  tag.otherBody = otherBody;
  return tag;
}

struct SolidBox {
  Vec3 center;
  Quat orientation = Quat::Identity();
  Vec3 halfExtents;
  Color color;
  Tag tag;
};

struct SolidSphere {
  Vec3 center;
  Quat orientation = Quat::Identity();
  double radius = 1;
  Color color;
  Tag tag;
};

// Capsule along its local y axis: a cylinder of half height `halfHeight` with
// hemispherical caps of `radius`.
struct SolidCapsule {
  Vec3 center;
  Quat orientation = Quat::Identity();
  double radius = 0.5;
  double halfHeight = 0.5;
  Color color;
  Tag tag;
};

// Triangle mesh in local coordinates, shared between frames. `id` is stable
// for the life of the mesh so a renderer may cache uploads by it.
struct TriangleMesh {
  std::uint64_t id = 0;
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
};

struct SolidMesh {
  Vec3 center;
  Quat orientation = Quat::Identity();
  std::shared_ptr<const TriangleMesh> mesh;
  Color color;
  Tag tag;
};

// Twelve edges of an oriented box (identity orientation for AABBs).
struct WireBox {
  Vec3 center;
  Quat orientation = Quat::Identity();
  Vec3 halfExtents;
  Color color;
  Tag tag;
};

struct Line {
  Vec3 from, to;
  Color color;
  Tag tag;
};

struct Point {
  Vec3 position;
  float sizePixels = 6;
  Color color;
  Tag tag;
};

// A line with a head at `to`.
struct Arrow {
  Vec3 from, to;
  Color color;
  Tag tag;
};

// Bounds on overlay text. The renderer builds about 5.5 KiB of triangles per
// character (glyph plus an eight-way outline), so unbounded text from a
// recording could take gigabytes; these keep a frame's text under ~100 MiB.
// Recording readers refuse more; the text geometry builder refuses it too.
inline constexpr std::size_t maxTextCharacters = 4096;        // one Text
inline constexpr std::size_t maxFrameTextCharacters = 16384;  // all Texts of a frame

// Screen-space text, pixels from the top-left corner.
struct Text {
  float x = 0, y = 0;
  float scale = 2;
  std::string text;
  Color color;
  Tag tag;
};

// Text anchored at a point in the world (body labels): the renderer projects
// the anchor and centres the text above it; anchors behind the camera draw nothing.
struct Label {
  Vec3 position;
  float scale = 1;
  std::string text;
  Color color;
  Tag tag;
  // Left out when it would cover a label drawn before it: a crowd of body
  // labels then reads instead of forming a white mass. Set by the viewer for
  // body labels; not recorded (recorded labels, the grid's, always draw).
  bool yieldsToEarlier = false;
};

// One body's state in a frame: what a viewer needs for --labels, --highlight,
// --follow and the overlay of a body, without the engine. Not drawn itself.
struct BodyInfo {
  std::int32_t index = 0;
  std::string name;  // the scene's name for the body, or empty
  Vec3 position = Vec3::Zero(), linearVelocity = Vec3::Zero(), angularVelocity = Vec3::Zero();
  Vec3 boundsMin = Vec3::Zero(), boundsMax = Vec3::Zero();  // world AABB of the collider
  std::int32_t contacts = 0;   // contact points shown for it in this frame
  std::int32_t treeLeaf = -1;  // its broad-phase tree leaf, and that leaf's parent (-1: none)
  std::int32_t treeParent = -1;
  bool isStatic = false, asleep = false;
  bool absent = false;  // not in the run at this frame (added later or removed): nothing drawn
};

struct Frame {
  std::vector<SolidBox> boxes;
  std::vector<SolidSphere> spheres;
  std::vector<SolidCapsule> capsules;
  std::vector<SolidMesh> meshes;
  std::vector<WireBox> wireBoxes;
  std::vector<Line> lines;
  std::vector<Point> points;
  std::vector<Arrow> arrows;
  std::vector<Text> texts;
  std::vector<Label> labels;
  std::vector<BodyInfo> bodies;  // state, not primitives: not counted below

  void clear();
  bool empty() const;
  std::size_t primitiveCount() const;
};

// The sizes of a frame's primitive lists at one moment. fillTagsSince gives
// every primitive added after it the fields of `tag` that it has not set, so
// a producer tags a whole emission (one body, one layer) in one place.
struct FrameMark {
  std::array<std::size_t, 10> sizes{};
};
FrameMark markOf(const Frame& frame);
void fillTagsSince(Frame& frame, const FrameMark& mark, const Tag& tag);

}  // namespace physdbg::debugdraw
