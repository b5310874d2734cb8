#include "debugdraw/recording.h"

#include <bit>
#include <stdexcept>

namespace physdbg::debugdraw {
namespace {

constexpr char magic[8] = {'P', 'H', 'Y', 'S', 'D', 'B', 'G', 'R'};
constexpr std::uint32_t meshTag = 1;
constexpr std::uint32_t frameTag = 2;
// A chunk larger than this is corruption, not data (1000x a 100k-primitive frame).
constexpr std::uint64_t maxChunkBytes = std::uint64_t{1} << 34;

class ByteWriter {
 public:
  std::string bytes;
  void u32(std::uint32_t value) { little(value, 4); }
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

 private:
  void little(std::uint64_t value, int count) {
    for (int i = 0; i < count; ++i) bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  }
};

class ByteReader {
 public:
  ByteReader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  std::uint32_t u32() { return static_cast<std::uint32_t>(little(4)); }
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
  std::string text() {
    const std::uint32_t size = u32();
    need(size);
    std::string s = bytes_.substr(offset_, size);
    offset_ += size;
    return s;
  }
  // A count of items of at least `itemBytes` each, checked against what is left.
  std::uint32_t count(std::size_t itemBytes) {
    const std::uint32_t n = u32();
    need(static_cast<std::size_t>(n) * itemBytes);
    return n;
  }
  bool done() const { return offset_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("recording '" + path_ + "': " + what);
  }

 private:
  void need(std::size_t size) const {
    if (bytes_.size() - offset_ < size) fail("corrupt chunk (a list runs past its end)");
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
  const std::string& path_;
  std::size_t offset_ = 0;
};

void writeView(ByteWriter& out, const View& view) {
  out.vec3(view.eye);
  out.vec3(view.target);
  out.vec3(view.up);
  out.f64(view.fovYDegrees);
  out.u32(view.orthographic ? 1 : 0);
  out.f64(view.orthoHeight);
}

View readView(ByteReader& in) {
  View view;
  view.eye = in.vec3();
  view.target = in.vec3();
  view.up = in.vec3();
  view.fovYDegrees = in.f64();
  view.orthographic = in.u32() != 0;
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
  mesh->vertices.resize(in.count(12));
  for (Eigen::Vector3f& v : mesh->vertices) {
    const float x = in.f32(), y = in.f32(), z = in.f32();
    v = {x, y, z};
  }
  mesh->indices.resize(in.count(4));
  for (std::uint32_t& index : mesh->indices) {
    index = in.u32();
    if (index >= mesh->vertices.size()) in.fail("mesh index out of range");
  }
  return mesh;
}

std::string encodeFrame(const RecordedFrame& recorded) {
  const Frame& f = recorded.frame;
  ByteWriter out;
  out.u32(static_cast<std::uint32_t>(recorded.index));
  writeView(out, recorded.view);
  auto list = [&](const auto& items, auto&& each) {
    out.u32(static_cast<std::uint32_t>(items.size()));
    for (const auto& item : items) each(item);
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
  return out.bytes;
}

template <typename Item, typename Decode>
void readList(ByteReader& in, std::size_t itemBytes, std::vector<Item>& items, Decode&& decode) {
  items.resize(in.count(itemBytes));
  for (Item& item : items) decode(item);
}

void decodeFrame(ByteReader& in, const std::map<std::uint64_t, std::shared_ptr<const TriangleMesh>>& meshes,
                 RecordedFrame& out) {
  out.view = readView(in);
  Frame& f = out.frame;
  f.clear();
  // Exact item sizes (texts: without their characters) bound each count by the bytes left.
  readList(in, 96, f.boxes, [&](SolidBox& b) { b.center = in.vec3(), b.orientation = in.quat(), b.halfExtents = in.vec3(), b.color = in.color(); });
  readList(in, 80, f.spheres, [&](SolidSphere& s) { s.center = in.vec3(), s.orientation = in.quat(), s.radius = in.f64(), s.color = in.color(); });
  readList(in, 88, f.capsules, [&](SolidCapsule& c) {
    c.center = in.vec3(), c.orientation = in.quat(), c.radius = in.f64(), c.halfHeight = in.f64(), c.color = in.color();
  });
  readList(in, 80, f.meshes, [&](SolidMesh& m) {
    m.center = in.vec3(), m.orientation = in.quat();
    const auto found = meshes.find(in.u64());
    if (found == meshes.end()) in.fail("frame " + std::to_string(out.index) + " uses a mesh that was never defined");
    m.mesh = found->second;
    m.color = in.color();
  });
  readList(in, 96, f.wireBoxes, [&](WireBox& b) { b.center = in.vec3(), b.orientation = in.quat(), b.halfExtents = in.vec3(), b.color = in.color(); });
  readList(in, 64, f.lines, [&](Line& l) { l.from = in.vec3(), l.to = in.vec3(), l.color = in.color(); });
  readList(in, 44, f.points, [&](Point& p) { p.position = in.vec3(), p.sizePixels = in.f32(), p.color = in.color(); });
  readList(in, 64, f.arrows, [&](Arrow& a) { a.from = in.vec3(), a.to = in.vec3(), a.color = in.color(); });
  readList(in, 32, f.texts, [&](Text& t) { t.x = in.f32(), t.y = in.f32(), t.scale = in.f32(), t.text = in.text(), t.color = in.color(); });
  if (!in.done()) in.fail("frame " + std::to_string(out.index) + " has trailing bytes");
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
  ByteWriter head;
  head.u32(tag);
  head.u64(payload.size());
  file_.write(head.bytes.data(), static_cast<std::streamsize>(head.bytes.size()));
  file_.write(payload.data(), static_cast<std::streamsize>(payload.size()));
}

void RecordingWriter::write(const RecordedFrame& recorded) {
  if (recorded.index < 0) throw std::invalid_argument("recording: negative frame index");
  for (const SolidMesh& mesh : recorded.frame.meshes) {
    if (!mesh.mesh) throw std::invalid_argument("recording: solid mesh without a mesh");
    if (meshesWritten_.insert(mesh.mesh->id).second) writeChunk(meshTag, encodeMesh(*mesh.mesh));
  }
  writeChunk(frameTag, encodeFrame(recorded));
}

void RecordingWriter::close() {
  file_.flush();
  if (!file_) throw std::runtime_error("writing recording '" + path_ + "' failed");
  file_.close();
}

RecordingReader::RecordingReader(const std::string& path) : path_(path), file_(path, std::ios::binary) {
  if (!file_) throw std::invalid_argument("cannot open recording '" + path + "'");
  std::string header(12, '\0');
  file_.read(header.data(), 12);
  if (file_.gcount() != 12 || header.compare(0, 8, magic, 8) != 0)
    throw std::invalid_argument("'" + path + "' is not a physdbg recording");
  const std::string versionBytes = header.substr(8);
  ByteReader reader(versionBytes, path_);
  const std::uint32_t version = reader.u32();
  if (version == 0 || version > recordingVersion)
    reader.fail("version " + std::to_string(version) + " (this physdbg reads up to " +
                std::to_string(recordingVersion) + ")");
}

bool RecordingReader::next(RecordedFrame& out, int first, int last) {
  while (true) {
    std::string head(12, '\0');
    file_.read(head.data(), 12);
    if (file_.gcount() == 0) return false;
    ByteReader headReader(head, path_);
    if (file_.gcount() != 12) headReader.fail("truncated chunk header");
    const std::uint32_t tag = headReader.u32();
    const std::uint64_t size = headReader.u64();
    if (size > maxChunkBytes) headReader.fail("chunk of " + std::to_string(size) + " bytes");
    if (tag == frameTag && size >= 4) {
      std::string index(4, '\0');
      file_.read(index.data(), 4);
      ByteReader indexReader(index, path_);
      if (file_.gcount() != 4) indexReader.fail("truncated frame");
      const int frameIndex = static_cast<int>(indexReader.u32());
      if (frameIndex < first || frameIndex >= last) {
        file_.seekg(static_cast<std::streamoff>(size - 4), std::ios::cur);
        continue;
      }
      std::string payload(size - 4, '\0');
      file_.read(payload.data(), static_cast<std::streamsize>(payload.size()));
      ByteReader reader(payload, path_);
      if (static_cast<std::uint64_t>(file_.gcount()) != size - 4) reader.fail("truncated frame");
      out.index = frameIndex;
      decodeFrame(reader, meshes_, out);
      return true;
    }
    std::string payload(size, '\0');
    file_.read(payload.data(), static_cast<std::streamsize>(size));
    ByteReader reader(payload, path_);
    if (static_cast<std::uint64_t>(file_.gcount()) != size) reader.fail("truncated chunk");
    if (tag == meshTag) {
      std::shared_ptr<const TriangleMesh> mesh = decodeMesh(reader);
      meshes_[mesh->id] = std::move(mesh);
    }
  }
}

}  // namespace physdbg::debugdraw
