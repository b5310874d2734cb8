#include "debugdraw/recording.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace physdbg::debugdraw {
namespace {

constexpr char magic[8] = {'P', 'H', 'Y', 'S', 'D', 'B', 'G', 'R'};
constexpr std::uint32_t meshTag = 1;
constexpr std::uint32_t frameTag = 2;
constexpr std::uint64_t fileHeadBytes = 12;
constexpr std::uint64_t chunkHeadBytes = 12;
constexpr std::uint64_t maxFrameIndex = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
// Quaternion lengths the renderer can normalise without losing the rotation.
constexpr double minRotationNorm = 1e-6, maxRotationNorm = 1e6;
// The layer bits a tag may name: Shapes .. Grid in versions 2 and 3, and
// Mesh from version 4. A new layer is a new format version: an older reader
// could not say what to draw for it.
constexpr std::uint32_t knownLayerBits = allLayerBits;
constexpr std::uint32_t knownLayerBitsOf(std::uint32_t version) {
  return version >= 4 ? allLayerBits : (static_cast<std::uint32_t>(Layer::Grid) << 1) - 1;
}
// Encoded sizes in versions 2 and 3: a tag (u32 layer, five i32) and the fixed part
// of a label (before its tag) and of a body, strings without their characters.
constexpr std::size_t tagBytes = 4 + 5 * 4;
constexpr std::size_t labelBytes = 24 + 4 + 4 + 16;
constexpr std::size_t bodyBytes = 4 + 4 + 5 * 24 + 3 * 4 + 1;
constexpr std::uint8_t staticFlag = 1, asleepFlag = 2, absentFlag = 4;  // absent: version 3

[[noreturn]] void refuse(const std::string& name, const std::string& what) {
  throw std::invalid_argument("recording '" + name + "': " + what);
}

class ByteWriter {
 public:
  std::string bytes;
  void u8(std::uint8_t value) { little(value, 1); }
  void u32(std::uint32_t value) { little(value, 4); }
  void i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }
  void u64(std::uint64_t value) { little(value, 8); }
  void f32(float value) { u32(std::bit_cast<std::uint32_t>(value)); }
  void f64(double value) { u64(std::bit_cast<std::uint64_t>(value)); }
  void vec3(const Vec3& v) {
    for (int i = 0; i < 3; ++i) f64(v[i]);
  }
  void quat(const Quat& q) {
    for (const double c : {q.w(), q.x(), q.y(), q.z()}) f64(c);
  }
  void color(const Color& c) {
    for (const float channel : {c.r, c.g, c.b, c.a}) f32(channel);
  }
  void text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    bytes += s;
  }
  void tag(const Tag& t) {
    u32(t.layer);
    for (const std::int32_t field : {t.body, t.otherBody, t.node, t.parent, t.depth}) i32(field);
  }

 private:
  void little(std::uint64_t value, int count) {
    for (int i = 0; i < count; ++i) bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  }
};

// Decodes one chunk's payload. Every count is checked against its limit and
// against the bytes left in the payload before anything is allocated for it;
// `context` ("frame 5, points: ") prefixes the messages.
class ByteReader {
 public:
  ByteReader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}
  std::uint8_t u8() { return static_cast<std::uint8_t>(little(1)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(little(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::uint64_t u64() { return little(8); }
  float f32() { return std::bit_cast<float>(u32()); }
  double f64() { return std::bit_cast<double>(u64()); }
  Vec3 vec3() {
    const double x = f64(), y = f64(), z = f64();
    return {x, y, z};
  }
  Quat quat() {
    const double w = f64(), x = f64(), y = f64(), z = f64();
    return Quat(w, x, y, z);
  }
  Color color() {
    const float r = f32(), g = f32(), b = f32(), a = f32();
    return {r, g, b, a};
  }
  Tag tag() {
    Tag t;
    t.layer = u32();
    for (std::int32_t* field : {&t.body, &t.otherBody, &t.node, &t.parent, &t.depth}) *field = i32();
    return t;
  }
  // `what` names the string in messages ("a text", "a name").
  std::string text(const char* what = "a text") {
    const std::uint32_t size = u32();
    if (size > maxTextCharacters)
      fail(std::string(what) + " of " + std::to_string(size) + " characters, over the limit of " +
           std::to_string(maxTextCharacters) + " per text");
    need(size);
    std::string s = bytes_.substr(offset_, size);
    offset_ += size;
    return s;
  }
  // A count of items of at least `itemBytes` each, checked against `limit` and what is left.
  std::uint32_t count(std::size_t itemBytes, std::uint32_t limit) {
    const std::uint32_t n = u32();
    if (n > limit) fail(std::to_string(n) + " items, over the limit of " + std::to_string(limit));
    if (n * itemBytes > left())
      fail(std::to_string(n) + " items of " + std::to_string(itemBytes) + " bytes run past the end of the chunk (" +
           std::to_string(left()) + " bytes left)");
    return n;
  }
  void context(const std::string& prefix) { context_ = prefix; }
  bool done() const { return offset_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& what) const { refuse(name_, context_ + what); }

 private:
  std::size_t left() const { return bytes_.size() - offset_; }
  void need(std::size_t size) const {
    if (left() < size)
      fail("a value runs past the end of the chunk (" + std::to_string(size) + " bytes needed, " +
           std::to_string(left()) + " left)");
  }
  std::uint64_t little(int count) {
    need(static_cast<std::size_t>(count));
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[offset_ + i])) << (8 * i);
    offset_ += static_cast<std::size_t>(count);
    return value;
  }
  const std::string& bytes_;
  const std::string& name_;
  std::string context_;
  std::size_t offset_ = 0;
};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The checks behind the limits, shared by reader and writer: each item's
// first problem as words, empty when it can be drawn. NaN fails every range.
class ItemCheck {
 public:
  std::string problem;

  ItemCheck& position(const Vec3& v, const char* what) {
    for (int i = 0; i < 3; ++i) within(v[i], -maxCoordinate, maxCoordinate, what);
    return *this;
  }
  ItemCheck& lengths(const Vec3& v, const char* what) {
    for (int i = 0; i < 3; ++i) within(v[i], 0, maxCoordinate, what);
    return *this;
  }
  ItemCheck& rotation(const Quat& q) {
    const double norm = q.coeffs().allFinite() ? q.norm() : std::nan("");
    return within(norm, minRotationNorm, maxRotationNorm, "orientation length");
  }
  ItemCheck& color(const Color& c) {
    for (const float channel : {c.r, c.g, c.b, c.a}) finite(channel, "colour");
    return *this;
  }
  ItemCheck& finite(double value, const char* what) {
    if (problem.empty() && !std::isfinite(value)) problem = std::string(what) + " is " + number(value);
    return *this;
  }
  ItemCheck& within(double value, double low, double high, const char* what) {
    if (problem.empty() && !(value >= low && value <= high))
      problem = std::string(what) + " " + number(value) + " is outside " + number(low) + ".." + number(high);
    return *this;
  }
  ItemCheck& atLeast(std::int32_t value, std::int32_t low, const char* what) {
    if (problem.empty() && value < low)
      problem = std::string(what) + " " + std::to_string(value) + " is below " + std::to_string(low);
    return *this;
  }
  ItemCheck& ordered(const Vec3& low, const Vec3& high, const char* what) {
    for (int i = 0; i < 3; ++i)
      if (problem.empty() && !(low[i] <= high[i]))
        problem = std::string(what) + " " + "xyz"[i] + ": min " + number(low[i]) + " is above max " + number(high[i]);
    return *this;
  }
};

template <typename Box>
std::string problemOfBox(const Box& b) {
  return ItemCheck()
      .position(b.center, "centre")
      .rotation(b.orientation)
      .lengths(b.halfExtents, "half extent")
      .color(b.color)
      .problem;
}

std::string problemOf(const SolidBox& b) { return problemOfBox(b); }
std::string problemOf(const WireBox& b) { return problemOfBox(b); }

std::string problemOf(const SolidSphere& s) {
  return ItemCheck()
      .position(s.center, "centre")
      .rotation(s.orientation)
      .within(s.radius, 0, maxCoordinate, "radius")
      .color(s.color)
      .problem;
}

std::string problemOf(const SolidCapsule& c) {
  return ItemCheck()
      .position(c.center, "centre")
      .rotation(c.orientation)
      .within(c.radius, 0, maxCoordinate, "radius")
      .within(c.halfHeight, 0, maxCoordinate, "half height")
      .color(c.color)
      .problem;
}

std::string problemOf(const SolidMesh& m) {
  if (!m.mesh) return "solid mesh without a mesh";
  return ItemCheck().position(m.center, "centre").rotation(m.orientation).color(m.color).problem;
}

template <typename Segment>
std::string problemOfSegment(const Segment& s) {
  return ItemCheck().position(s.from, "start").position(s.to, "end").color(s.color).problem;
}

std::string problemOf(const Line& l) { return problemOfSegment(l); }
std::string problemOf(const Arrow& a) { return problemOfSegment(a); }

std::string problemOf(const Point& p) {
  return ItemCheck()
      .position(p.position, "position")
      .within(p.sizePixels, 0, maxPointPixels, "size in pixels")
      .color(p.color)
      .problem;
}

std::string lengthProblem(const std::string& text, const char* what) {
  if (text.size() <= maxTextCharacters) return {};
  return std::string(what) + " of " + std::to_string(text.size()) + " characters, over the limit of " +
         std::to_string(maxTextCharacters) + " per text";
}

std::string problemOf(const Text& t) {
  if (std::string problem = lengthProblem(t.text, "a text"); !problem.empty()) return problem;
  return ItemCheck()
      .within(t.x, -maxTextPixels, maxTextPixels, "x")
      .within(t.y, -maxTextPixels, maxTextPixels, "y")
      .within(t.scale, minTextScale, maxTextScale, "scale")
      .color(t.color)
      .problem;
}

std::string problemOf(const Label& l) {
  if (std::string problem = lengthProblem(l.text, "a text"); !problem.empty()) return problem;
  return ItemCheck()
      .position(l.position, "position")
      .within(l.scale, minTextScale, maxTextScale, "scale")
      .color(l.color)
      .problem;
}

std::string problemOf(const BodyInfo& b) {
  if (std::string problem = lengthProblem(b.name, "a name"); !problem.empty()) return problem;
  return ItemCheck()
      .atLeast(b.index, 0, "index")
      .position(b.position, "position")
      .position(b.linearVelocity, "linear velocity")
      .position(b.angularVelocity, "angular velocity")
      .position(b.boundsMin, "bounds min")
      .position(b.boundsMax, "bounds max")
      .ordered(b.boundsMin, b.boundsMax, "bounds")
      .atLeast(b.contacts, 0, "contacts")
      .atLeast(b.treeLeaf, -1, "tree leaf")
      .atLeast(b.treeParent, -1, "tree parent")
      .problem;
}

// Layer 0 (untagged) or exactly one known layer bit; body and tree fields -1 (none) or more.
std::string tagProblem(const Tag& tag) {
  if (tag.layer != 0 && (!std::has_single_bit(tag.layer) || (tag.layer & knownLayerBits) == 0))
    return "tag layer " + std::to_string(tag.layer) + " is neither 0 nor one known layer bit (1 .. " +
           std::to_string(static_cast<std::uint32_t>(Layer::Mesh)) + ")";
  return ItemCheck()
      .atLeast(tag.body, -1, "tag body")
      .atLeast(tag.otherBody, -1, "tag other body")
      .atLeast(tag.node, -1, "tag node")
      .atLeast(tag.parent, -1, "tag parent")
      .atLeast(tag.depth, -1, "tag depth")
      .problem;
}

template <typename Item>
std::string itemProblem(const Item& item) {
  std::string problem = problemOf(item);
  if constexpr (requires { item.tag; })
    if (problem.empty()) problem = tagProblem(item.tag);
  return problem;
}

template <typename Item>
std::string listProblem(const std::vector<Item>& items, const char* list) {
  if (items.size() > maxListItems)
    return std::string(list) + ": " + std::to_string(items.size()) + " items, over the limit of " +
           std::to_string(maxListItems);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string problem = itemProblem(items[i]);
    if (!problem.empty()) return std::string(list) + " item " + std::to_string(i) + ": " + problem;
  }
  return {};
}

std::string viewProblem(const View& view) {
  const std::string problem = ItemCheck()
                                  .position(view.eye, "eye")
                                  .position(view.target, "target")
                                  .position(view.up, "up")
                                  .within(view.fovYDegrees, 0.001, 179.999, "vertical field of view")
                                  .within(view.orthoHeight, 0, maxCoordinate, "orthographic height")
                                  .problem;
  return problem.empty() ? problem : "view: " + problem;
}

// Texts and labels are both drawn as glyph geometry, so they share one budget.
std::string textTotalProblem(const Frame& frame) {
  std::size_t characters = 0;
  for (const Text& text : frame.texts) characters += text.text.size();
  for (const Label& label : frame.labels) characters += label.text.size();
  if (characters <= maxFrameTextCharacters) return {};
  return std::to_string(characters) + " characters of text in texts and labels, over the limit of " +
         std::to_string(maxFrameTextCharacters) + " per frame";
}

// The frame's first value beyond the limits, named by frame, list and item.
std::string frameProblem(const RecordedFrame& recorded) {
  const Frame& f = recorded.frame;
  if (recorded.shownLayers.empty() || (recorded.shownLayers.bits & ~knownLayerBits) != 0)
    return "frame " + std::to_string(recorded.index) + ", shown layers " + std::to_string(recorded.shownLayers.bits) +
           " name no layer or an unknown one";
  for (const std::string& problem :
       {viewProblem(recorded.view), listProblem(f.boxes, "solid boxes"), listProblem(f.spheres, "solid spheres"),
        listProblem(f.capsules, "capsules"), listProblem(f.meshes, "solid meshes"),
        listProblem(f.wireBoxes, "wire boxes"), listProblem(f.lines, "lines"), listProblem(f.points, "points"),
        listProblem(f.arrows, "arrows"), listProblem(f.texts, "texts"), listProblem(f.labels, "labels"),
        listProblem(f.bodies, "bodies"), textTotalProblem(f)})
    if (!problem.empty()) return "frame " + std::to_string(recorded.index) + ", " + problem;
  return {};
}

std::string meshProblem(const TriangleMesh& mesh) {
  const std::string prefix = "mesh " + std::to_string(mesh.id) + ": ";
  if (mesh.vertices.size() > maxMeshVertices)
    return prefix + std::to_string(mesh.vertices.size()) + " vertices, over the limit of " +
           std::to_string(maxMeshVertices);
  if (mesh.indices.size() > maxMeshIndices)
    return prefix + std::to_string(mesh.indices.size()) + " indices, over the limit of " +
           std::to_string(maxMeshIndices);
  if (mesh.indices.size() % 3 != 0)
    return prefix + std::to_string(mesh.indices.size()) + " indices, not three per triangle";
  for (const std::uint32_t index : mesh.indices)
    if (index >= mesh.vertices.size()) return prefix + "index " + std::to_string(index) + " out of range";
  ItemCheck check;
  for (const Eigen::Vector3f& vertex : mesh.vertices) check.position(vertex.cast<double>(), "vertex");
  return check.problem.empty() ? check.problem : prefix + check.problem;
}

void writeView(ByteWriter& out, const View& view) {
  out.vec3(view.eye);
  out.vec3(view.target);
  out.vec3(view.up);
  out.f64(view.fovYDegrees);
  out.u32(view.orthographic ? 1 : 0);
  out.f64(view.orthoHeight);
}

View readView(ByteReader& in) {
  in.context("view: ");
  View view;
  view.eye = in.vec3();
  view.target = in.vec3();
  view.up = in.vec3();
  view.fovYDegrees = in.f64();
  const std::uint32_t orthographic = in.u32();
  if (orthographic > 1) in.fail("orthographic flag " + std::to_string(orthographic) + " is neither 0 nor 1");
  view.orthographic = orthographic == 1;
  view.orthoHeight = in.f64();
  return view;
}

std::string encodeMesh(const TriangleMesh& mesh) {
  ByteWriter out;
  out.u64(mesh.id);
  out.u32(static_cast<std::uint32_t>(mesh.vertices.size()));
  for (const Eigen::Vector3f& v : mesh.vertices)
    for (int i = 0; i < 3; ++i) out.f32(v[i]);
  out.u32(static_cast<std::uint32_t>(mesh.indices.size()));
  for (const std::uint32_t index : mesh.indices) out.u32(index);
  return out.bytes;
}

std::shared_ptr<const TriangleMesh> decodeMesh(ByteReader& in) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->id = in.u64();
  in.context("mesh " + std::to_string(mesh->id) + ", vertices: ");
  mesh->vertices.resize(in.count(12, maxMeshVertices));
  for (Eigen::Vector3f& v : mesh->vertices) {
    const float x = in.f32(), y = in.f32(), z = in.f32();
    v = {x, y, z};
  }
  in.context("mesh " + std::to_string(mesh->id) + ", indices: ");
  mesh->indices.resize(in.count(4, maxMeshIndices));
  for (std::uint32_t& index : mesh->indices) index = in.u32();
  in.context("");
  if (!in.done()) in.fail("mesh " + std::to_string(mesh->id) + " has trailing bytes");
  if (const std::string problem = meshProblem(*mesh); !problem.empty()) in.fail(problem);
  return mesh;
}

void writeBody(ByteWriter& out, const BodyInfo& b) {
  out.i32(b.index);
  out.text(b.name);
  for (const Vec3* v : {&b.position, &b.linearVelocity, &b.angularVelocity, &b.boundsMin, &b.boundsMax}) out.vec3(*v);
  for (const std::int32_t field : {b.contacts, b.treeLeaf, b.treeParent}) out.i32(field);
  out.u8(static_cast<std::uint8_t>((b.isStatic ? staticFlag : 0) | (b.asleep ? asleepFlag : 0) |
                                   (b.absent ? absentFlag : 0)));
}

// `frame` and `item` name the body for flag bits the format does not define.
void readBody(ByteReader& in, BodyInfo& b, int frame, std::ptrdiff_t item, std::uint32_t version) {
  b.index = in.i32();
  b.name = in.text("a name");
  for (Vec3* v : {&b.position, &b.linearVelocity, &b.angularVelocity, &b.boundsMin, &b.boundsMax}) *v = in.vec3();
  for (std::int32_t* field : {&b.contacts, &b.treeLeaf, &b.treeParent}) *field = in.i32();
  const std::uint8_t flags = in.u8();
  const std::uint8_t known = staticFlag | asleepFlag | (version >= 3 ? absentFlag : 0);
  if ((flags & ~known) != 0) {
    in.context("");
    in.fail("frame " + std::to_string(frame) + ", bodies item " + std::to_string(item) + ": flags " +
            std::to_string(flags) + " set bits other than 0 (static), 1 (asleep)" +
            (version >= 3 ? " and 2 (absent)" : " (bit 2, absent, is version 3's)"));
  }
  b.isStatic = (flags & staticFlag) != 0;
  b.asleep = (flags & asleepFlag) != 0;
  b.absent = (flags & absentFlag) != 0;
}

std::string encodeFrame(const RecordedFrame& recorded) {
  const Frame& f = recorded.frame;
  ByteWriter out;
  out.u32(static_cast<std::uint32_t>(recorded.index));
  writeView(out, recorded.view);
  out.u32(recorded.shownLayers.bits);
  auto list = [&](const auto& items, auto&& each) {
    out.u32(static_cast<std::uint32_t>(items.size()));
    for (const auto& item : items) {
      each(item);
      if constexpr (requires { item.tag; }) out.tag(item.tag);
    }
  };
  list(f.boxes, [&](const SolidBox& b) { out.vec3(b.center), out.quat(b.orientation), out.vec3(b.halfExtents), out.color(b.color); });
  list(f.spheres, [&](const SolidSphere& s) { out.vec3(s.center), out.quat(s.orientation), out.f64(s.radius), out.color(s.color); });
  list(f.capsules, [&](const SolidCapsule& c) {
    out.vec3(c.center), out.quat(c.orientation), out.f64(c.radius), out.f64(c.halfHeight), out.color(c.color);
  });
  list(f.meshes, [&](const SolidMesh& m) { out.vec3(m.center), out.quat(m.orientation), out.u64(m.mesh->id), out.color(m.color); });
  list(f.wireBoxes, [&](const WireBox& b) { out.vec3(b.center), out.quat(b.orientation), out.vec3(b.halfExtents), out.color(b.color); });
  list(f.lines, [&](const Line& l) { out.vec3(l.from), out.vec3(l.to), out.color(l.color); });
  list(f.points, [&](const Point& p) { out.vec3(p.position), out.f32(p.sizePixels), out.color(p.color); });
  list(f.arrows, [&](const Arrow& a) { out.vec3(a.from), out.vec3(a.to), out.color(a.color); });
  list(f.texts, [&](const Text& t) { out.f32(t.x), out.f32(t.y), out.f32(t.scale), out.text(t.text), out.color(t.color); });
  list(f.labels, [&](const Label& l) { out.vec3(l.position), out.f32(l.scale), out.text(l.text), out.color(l.color); });
  list(f.bodies, [&](const BodyInfo& b) { writeBody(out, b); });
  return out.bytes;
}

// Reads one list of a frame: from version 2 on every primitive is followed by
// its tag, which `itemBytes` (the version 1 size) does not include.
class ListReader {
 public:
  ListReader(ByteReader& in, int frame, std::uint32_t version) : in_(in), frame_(frame), version_(version) {}
  template <typename Item, typename Decode>
  void operator()(const char* list, std::size_t itemBytes, std::vector<Item>& items, Decode&& decode) {
    constexpr bool tagged = requires(Item item) { item.tag; };
    const bool withTags = tagged && version_ >= 2;
    in_.context("frame " + std::to_string(frame_) + ", " + list + ": ");
    items.resize(in_.count(itemBytes + (withTags ? tagBytes : 0), maxListItems));
    for (Item& item : items) {
      decode(item);
      if constexpr (tagged)
        if (withTags) item.tag = in_.tag();
    }
  }

 private:
  ByteReader& in_;
  int frame_;
  std::uint32_t version_;
};

// Version 1 frames hold only the layers that were shown.
LayerSet readShownLayers(ByteReader& in, std::uint32_t version) {
  const std::uint32_t known = knownLayerBitsOf(version);
  if (version < 2) return LayerSet{known};
  const std::uint32_t bits = in.u32();
  if (bits == 0 || (bits & ~known) != 0)
    in.fail("shown layers " + std::to_string(bits) + " name no layer or an unknown one (known bits: " +
            std::to_string(known) + ")");
  return LayerSet{bits};
}

void decodeFrame(ByteReader& in, const std::map<std::uint64_t, std::shared_ptr<const TriangleMesh>>& meshes,
                 std::uint32_t version, RecordedFrame& out) {
  out.view = readView(in);
  out.shownLayers = readShownLayers(in, version);
  Frame& f = out.frame;
  f.clear();
  ListReader readList(in, out.index, version);
  // Exact item sizes (texts: without their characters) bound each count by the bytes left.
  readList("solid boxes", 96, f.boxes, [&](SolidBox& b) { b.center = in.vec3(), b.orientation = in.quat(), b.halfExtents = in.vec3(), b.color = in.color(); });
  readList("solid spheres", 80, f.spheres, [&](SolidSphere& s) { s.center = in.vec3(), s.orientation = in.quat(), s.radius = in.f64(), s.color = in.color(); });
  readList("capsules", 88, f.capsules, [&](SolidCapsule& c) {
    c.center = in.vec3(), c.orientation = in.quat(), c.radius = in.f64(), c.halfHeight = in.f64(), c.color = in.color();
  });
  readList("solid meshes", 80, f.meshes, [&](SolidMesh& m) {
    m.center = in.vec3(), m.orientation = in.quat();
    const std::uint64_t id = in.u64();
    const auto found = meshes.find(id);
    if (found == meshes.end()) in.fail("mesh " + std::to_string(id) + " was never defined");
    m.mesh = found->second;
    m.color = in.color();
  });
  readList("wire boxes", 96, f.wireBoxes, [&](WireBox& b) { b.center = in.vec3(), b.orientation = in.quat(), b.halfExtents = in.vec3(), b.color = in.color(); });
  readList("lines", 64, f.lines, [&](Line& l) { l.from = in.vec3(), l.to = in.vec3(), l.color = in.color(); });
  readList("points", 44, f.points, [&](Point& p) { p.position = in.vec3(), p.sizePixels = in.f32(), p.color = in.color(); });
  readList("arrows", 64, f.arrows, [&](Arrow& a) { a.from = in.vec3(), a.to = in.vec3(), a.color = in.color(); });
  readList("texts", 32, f.texts, [&](Text& t) { t.x = in.f32(), t.y = in.f32(), t.scale = in.f32(), t.text = in.text(), t.color = in.color(); });
  if (version >= 2) {
    readList("labels", labelBytes, f.labels, [&](Label& l) { l.position = in.vec3(), l.scale = in.f32(), l.text = in.text(), l.color = in.color(); });
    readList("bodies", bodyBytes, f.bodies, [&](BodyInfo& b) { readBody(in, b, out.index, &b - f.bodies.data(), version); });
  }
  in.context("");
  if (!in.done()) in.fail("frame " + std::to_string(out.index) + " has trailing bytes");
  if (const std::string problem = frameProblem(out); !problem.empty()) in.fail(problem);
}

}  // namespace

RecordingWriter::RecordingWriter(const std::string& path) : path_(path), file_(path, std::ios::binary) {
  if (!file_) throw std::runtime_error("cannot create recording '" + path + "'");
  ByteWriter header;
  header.bytes.assign(magic, sizeof magic);
  header.u32(recordingVersion);
  file_.write(header.bytes.data(), static_cast<std::streamsize>(header.bytes.size()));
}

void RecordingWriter::writeChunk(std::uint32_t tag, const std::string& payload) {
  if (payload.size() > maxChunkBytes)
    refuse(path_, "cannot write a chunk of " + std::to_string(payload.size()) + " bytes, over the limit of " +
                      std::to_string(maxChunkBytes));
  ByteWriter head;
  head.u32(tag);
  head.u64(payload.size());
  file_.write(head.bytes.data(), static_cast<std::streamsize>(head.bytes.size()));
  file_.write(payload.data(), static_cast<std::streamsize>(payload.size()));
}

// Refuses what a reader would refuse, so every recording written can be read back.
void RecordingWriter::write(const RecordedFrame& recorded) {
  if (recorded.index < 0) throw std::invalid_argument("recording: negative frame index");
  for (const SolidMesh& mesh : recorded.frame.meshes)
    if (!mesh.mesh) throw std::invalid_argument("recording: solid mesh without a mesh");
  if (const std::string problem = frameProblem(recorded); !problem.empty())
    refuse(path_, "cannot write " + problem);
  for (const SolidMesh& mesh : recorded.frame.meshes) {
    if (meshesWritten_.contains(mesh.mesh->id)) continue;
    if (const std::string problem = meshProblem(*mesh.mesh); !problem.empty()) refuse(path_, "cannot write " + problem);
    writeChunk(meshTag, encodeMesh(*mesh.mesh));
    meshesWritten_.insert(mesh.mesh->id);
  }
  writeChunk(frameTag, encodeFrame(recorded));
}

void RecordingWriter::close() {
  file_.flush();
  if (!file_) throw std::runtime_error("writing recording '" + path_ + "' failed");
  file_.close();
}

RecordingReader::RecordingReader(const std::string& path)
    : name_(path), stream_(std::make_unique<std::ifstream>(path, std::ios::binary)) {
  if (!*stream_) throw std::invalid_argument("cannot open recording '" + path + "'");
  readHeader();
}

RecordingReader::RecordingReader(std::unique_ptr<std::istream> stream, const std::string& name)
    : name_(name), stream_(std::move(stream)) {
  if (!stream_ || !*stream_) throw std::invalid_argument("cannot read recording '" + name + "'");
  readHeader();
}

void RecordingReader::fail(const std::string& what) const { refuse(name_, what); }

// Learns the length first: every later size is checked against what remains.
void RecordingReader::readHeader() {
  stream_->seekg(0, std::ios::end);
  const std::streamoff end = stream_->tellg();
  stream_->seekg(0, std::ios::beg);
  if (end < 0 || !*stream_) fail("cannot find its size (not a seekable file)");
  length_ = static_cast<std::uint64_t>(end);
  std::string header(fileHeadBytes, '\0');
  if (length_ >= fileHeadBytes) stream_->read(header.data(), static_cast<std::streamsize>(fileHeadBytes));
  if (length_ < fileHeadBytes || static_cast<std::uint64_t>(stream_->gcount()) != fileHeadBytes ||
      header.compare(0, 8, magic, 8) != 0)
    throw std::invalid_argument("'" + name_ + "' is not a physdbg recording");
  offset_ = fileHeadBytes;
  const std::string versionBytes = header.substr(8);
  version_ = ByteReader(versionBytes, name_).u32();
  if (version_ == 0) fail("version 0 is not a recording version");
  if (version_ > recordingVersion)
    fail("version " + std::to_string(version_) + " is not one this physdbg reads (versions 1 to " +
         std::to_string(recordingVersion) + "; a newer physdbg wrote it?)");
}

std::string RecordingReader::readBytes(std::uint64_t count) {
  if (count > remaining()) fail("internal: read past the end at byte offset " + std::to_string(offset_));
  std::string bytes(count, '\0');
  stream_->read(bytes.data(), static_cast<std::streamsize>(count));
  if (static_cast<std::uint64_t>(stream_->gcount()) != count)
    fail("truncated at byte offset " + std::to_string(offset_ + stream_->gcount()) + " (the file shrank?)");
  offset_ += count;
  return bytes;
}

void RecordingReader::skip(std::uint64_t count) {
  if (count > remaining()) fail("internal: seek past the end at byte offset " + std::to_string(offset_));
  stream_->seekg(static_cast<std::streamoff>(count), std::ios::cur);
  if (!*stream_) fail("cannot seek to byte offset " + std::to_string(offset_ + count));
  offset_ += count;
}

// The size a chunk declares is checked against the file before anything is
// read, allocated or skipped for it.
RecordingReader::ChunkHead RecordingReader::readChunkHead() {
  ChunkHead head;
  head.offset = offset_;
  if (remaining() < chunkHeadBytes)
    fail("truncated chunk header at byte offset " + std::to_string(offset_) + ": " + std::to_string(chunkHeadBytes) +
         " bytes needed, " + std::to_string(remaining()) + " remain");
  const std::string bytes = readBytes(chunkHeadBytes);
  ByteReader reader(bytes, name_);
  head.tag = reader.u32();
  head.size = reader.u64();
  if (head.size > remaining())
    fail("truncated chunk at byte offset " + std::to_string(head.offset) + ": declares " + std::to_string(head.size) +
         " bytes, " + std::to_string(remaining()) + " remain");
  if (head.size > maxChunkBytes)
    fail("chunk at byte offset " + std::to_string(head.offset) + " declares " + std::to_string(head.size) +
         " bytes, over the limit of " + std::to_string(maxChunkBytes));
  return head;
}

bool RecordingReader::readFrame(const ChunkHead& head, RecordedFrame& out, int first, int last) {
  const std::string where = "frame chunk at byte offset " + std::to_string(head.offset);
  if (head.size < 4) fail(where + " is " + std::to_string(head.size) + " bytes, too short for a frame index");
  const std::string indexBytes = readBytes(4);
  const std::uint64_t index = ByteReader(indexBytes, name_).u32();
  if (index > maxFrameIndex) fail(where + ": frame index " + std::to_string(index) + " is over " +
                                  std::to_string(maxFrameIndex));
  const int frameIndex = static_cast<int>(index);
  if (frameIndex < first || frameIndex >= last) {
    skip(head.size - 4);
    return false;
  }
  const std::string payload = readBytes(head.size - 4);
  ByteReader reader(payload, name_);
  out.index = frameIndex;
  decodeFrame(reader, meshes_, version_, out);
  return true;
}

void RecordingReader::readMesh(const ChunkHead& head) {
  const std::string payload = readBytes(head.size);
  ByteReader reader(payload, name_);
  std::shared_ptr<const TriangleMesh> mesh = decodeMesh(reader);
  if (meshes_.contains(mesh->id))
    fail("mesh chunk at byte offset " + std::to_string(head.offset) + " defines mesh " + std::to_string(mesh->id) +
         " a second time");
  meshes_[mesh->id] = std::move(mesh);
}

bool RecordingReader::next(RecordedFrame& out, int first, int last) {
  while (remaining() > 0) {
    const ChunkHead head = readChunkHead();
    if (head.tag == frameTag) {
      if (readFrame(head, out, first, last)) return true;
    } else if (head.tag == meshTag) {
      readMesh(head);
    } else {
      skip(head.size);
    }
  }
  return false;
}

std::vector<RecordedFrame> readRecordingBytes(std::string bytes, const std::string& name) {
  RecordingReader reader(std::make_unique<std::istringstream>(std::move(bytes), std::ios::binary), name);
  std::vector<RecordedFrame> frames;
  RecordedFrame frame;
  while (reader.next(frame)) frames.push_back(frame);
  return frames;
}

}  // namespace physdbg::debugdraw
