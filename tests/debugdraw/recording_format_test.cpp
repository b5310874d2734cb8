// The recording format: every primitive kind survives a round trip bit for
// bit, frame ranges skip frames, bad files are refused with clear messages.
// Hostile input, one test per class: oversize chunk declarations, truncation at
// every byte, random byte flips, over-long texts, non-finite values.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <random>
#include <sstream>
#include <unistd.h>

#include "debugdraw/recording.h"
#include "recording_test_support.h"
#include "render/text_geometry.h"

// Bytes requested from operator new on this thread while counting, so the
// hostile-input tests can bound what decoding a recording allocates.
namespace physdbg::recordingtesting {
thread_local bool countAllocations = false;
thread_local std::size_t allocatedBytes = 0;
}  // namespace physdbg::recordingtesting
using physdbg::recordingtesting::allocatedBytes;
using physdbg::recordingtesting::countAllocations;

// Sanitizer builds keep their own allocator: replacing two of the many global
// allocation functions there pairs a library's nothrow new with our free()
// (libLLVM in llvmpipe does exactly that). They count nothing; the allocation
// bounds are checked by the ordinary build.
#if defined(__SANITIZE_ADDRESS__)
#define PHYSDBG_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PHYSDBG_SANITIZED 1
#endif
#endif
#ifndef PHYSDBG_SANITIZED
// Every call goes through these symbols, never an inlined or specialised copy:
// GCC would see free() meet memory from operator new, and valgrind, which
// replaces the symbols, would see a copy's malloc() freed by its delete.
#if defined(__GNUC__) && !defined(__clang__)
#define PHYSDBG_WHOLE_FUNCTION [[gnu::noipa]]
#else
#define PHYSDBG_WHOLE_FUNCTION [[gnu::noinline]]
#endif
PHYSDBG_WHOLE_FUNCTION void* operator new(std::size_t size) {
  if (countAllocations) allocatedBytes += size;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
PHYSDBG_WHOLE_FUNCTION void operator delete(void* memory) noexcept { std::free(memory); }
PHYSDBG_WHOLE_FUNCTION void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
#undef PHYSDBG_WHOLE_FUNCTION
#endif

namespace {

using namespace physdbg::recordingtesting;

dd::Color randomColor(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0, 1);
  return {unit(random), unit(random), unit(random), unit(random)};
}

dd::Vec3 randomVector(std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1e7, 1e7);
  return {coordinate(random), coordinate(random), coordinate(random)};
}

dd::RecordedFrame randomFrame(std::mt19937& random, int index, const std::shared_ptr<const dd::TriangleMesh>& mesh) {
  dd::RecordedFrame recorded;
  recorded.index = index;
  recorded.view = {randomVector(random), randomVector(random), {0, 0, 1}, 33.3, index % 2 == 1, 17.25};
  dd::Frame& f = recorded.frame;
  const dd::Quat q = dd::Quat(0.3, -0.5, 0.7, 0.1).normalized();
  for (int i = 0; i < 3; ++i) {
    f.boxes.push_back({randomVector(random), q, randomVector(random).cwiseAbs(), randomColor(random)});
    f.spheres.push_back({randomVector(random), q, 0.1 + i, randomColor(random)});
    f.capsules.push_back({randomVector(random), q, 0.2, 0.3 + i, randomColor(random)});
    f.meshes.push_back({randomVector(random), q, mesh, randomColor(random)});
    f.wireBoxes.push_back({randomVector(random), q, randomVector(random).cwiseAbs(), randomColor(random)});
    f.lines.push_back({randomVector(random), randomVector(random), randomColor(random)});
    f.points.push_back({randomVector(random), 4.5f + i, randomColor(random)});
    f.arrows.push_back({randomVector(random), randomVector(random), randomColor(random)});
    f.texts.push_back({1.5f, 2.5f * i, 2, "frame " + std::to_string(index) + " text " + std::to_string(i),
                       randomColor(random)});
  }
  return recorded;
}

void expectSame(const dd::Vec3& a, const dd::Vec3& b) { EXPECT_EQ(a, b); }
void expectSame(const dd::Quat& a, const dd::Quat& b) { EXPECT_EQ(a.coeffs(), b.coeffs()); }
void expectSame(const dd::Color& a, const dd::Color& b) {
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.g, b.g);
  EXPECT_EQ(a.b, b.b);
  EXPECT_EQ(a.a, b.a);
}

void expectSameFrame(const dd::RecordedFrame& a, const dd::RecordedFrame& b) {
  EXPECT_EQ(a.index, b.index);
  expectSame(a.view.eye, b.view.eye);
  expectSame(a.view.target, b.view.target);
  expectSame(a.view.up, b.view.up);
  EXPECT_EQ(a.view.fovYDegrees, b.view.fovYDegrees);
  EXPECT_EQ(a.view.orthographic, b.view.orthographic);
  EXPECT_EQ(a.view.orthoHeight, b.view.orthoHeight);
  ASSERT_EQ(a.frame.primitiveCount(), b.frame.primitiveCount());
  for (std::size_t i = 0; i < a.frame.boxes.size(); ++i) {
    expectSame(a.frame.boxes[i].center, b.frame.boxes[i].center);
    expectSame(a.frame.boxes[i].orientation, b.frame.boxes[i].orientation);
    expectSame(a.frame.boxes[i].halfExtents, b.frame.boxes[i].halfExtents);
    expectSame(a.frame.boxes[i].color, b.frame.boxes[i].color);
    EXPECT_EQ(a.frame.spheres[i].radius, b.frame.spheres[i].radius);
    expectSame(a.frame.spheres[i].center, b.frame.spheres[i].center);
    EXPECT_EQ(a.frame.capsules[i].halfHeight, b.frame.capsules[i].halfHeight);
    expectSame(a.frame.capsules[i].orientation, b.frame.capsules[i].orientation);
    EXPECT_EQ(a.frame.meshes[i].mesh->id, b.frame.meshes[i].mesh->id);
    EXPECT_EQ(a.frame.meshes[i].mesh->vertices, b.frame.meshes[i].mesh->vertices);
    EXPECT_EQ(a.frame.meshes[i].mesh->indices, b.frame.meshes[i].mesh->indices);
    expectSame(a.frame.meshes[i].color, b.frame.meshes[i].color);
    expectSame(a.frame.wireBoxes[i].halfExtents, b.frame.wireBoxes[i].halfExtents);
    expectSame(a.frame.lines[i].to, b.frame.lines[i].to);
    EXPECT_EQ(a.frame.points[i].sizePixels, b.frame.points[i].sizePixels);
    expectSame(a.frame.arrows[i].from, b.frame.arrows[i].from);
    EXPECT_EQ(a.frame.texts[i].text, b.frame.texts[i].text);
    EXPECT_EQ(a.frame.texts[i].y, b.frame.texts[i].y);
    expectSame(a.frame.texts[i].color, b.frame.texts[i].color);
  }
}

std::shared_ptr<const dd::TriangleMesh> tetrahedron() {
  auto mesh = std::make_shared<dd::TriangleMesh>();
  mesh->id = 77;
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh->indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return mesh;
}

std::vector<dd::RecordedFrame> writeFrames(const std::string& path, int count) {
  std::mt19937 random(20261121);
  const auto mesh = tetrahedron();
  std::vector<dd::RecordedFrame> frames;
  dd::RecordingWriter writer(path);
  for (int i = 0; i < count; ++i) {
    frames.push_back(randomFrame(random, i, mesh));
    writer.write(frames.back());
  }
  writer.close();
  return frames;
}

TEST(Recording, EveryPrimitiveRoundTripsExactly) {
  const std::string path = tempPath("roundtrip");
  const auto frames = writeFrames(path, 4);
  dd::RecordingReader reader(path);
  dd::RecordedFrame read;
  for (const dd::RecordedFrame& written : frames) {
    ASSERT_TRUE(reader.next(read));
    expectSameFrame(written, read);
  }
  EXPECT_FALSE(reader.next(read));
  fs::remove(path);
}

// One kind of primitive per frame: a list that ends the payload must still fit.
TEST(Recording, FramesOfASingleKindRoundTrip) {
  const std::string path = tempPath("single");
  std::mt19937 random(3);
  const dd::RecordedFrame full = randomFrame(random, 0, tetrahedron());
  std::vector<dd::RecordedFrame> frames(9);
  frames[0].frame.boxes = full.frame.boxes;
  frames[1].frame.spheres = full.frame.spheres;
  frames[2].frame.capsules = full.frame.capsules;
  frames[3].frame.meshes = full.frame.meshes;
  frames[4].frame.wireBoxes = full.frame.wireBoxes;
  frames[5].frame.lines = full.frame.lines;
  frames[6].frame.points = full.frame.points;
  frames[7].frame.arrows = full.frame.arrows;
  frames[8].frame.texts = full.frame.texts;
  {
    dd::RecordingWriter writer(path);
    for (int i = 0; i < 9; ++i) {
      frames[i].index = i;
      writer.write(frames[i]);
    }
    writer.close();
  }
  dd::RecordingReader reader(path);
  dd::RecordedFrame read;
  for (int i = 0; i < 9; ++i) {
    ASSERT_TRUE(reader.next(read)) << "kind " << i;
    EXPECT_EQ(read.frame.primitiveCount(), 3u) << "kind " << i;
  }
  fs::remove(path);
}

TEST(Recording, FrameRangeSkipsOtherFrames) {
  const std::string path = tempPath("range");
  const auto frames = writeFrames(path, 6);
  dd::RecordingReader reader(path);
  dd::RecordedFrame read;
  ASSERT_TRUE(reader.next(read, 2, 4));
  expectSameFrame(frames[2], read);  // its mesh was defined before frame 0 and is still known
  ASSERT_TRUE(reader.next(read, 2, 4));
  expectSameFrame(frames[3], read);
  EXPECT_FALSE(reader.next(read, 2, 4));
  fs::remove(path);
}

TEST(Recording, BadFilesAreRefusedNamingThePath) {
  const std::string path = tempPath("bad");
  auto expectRefused = [&](const std::string& content, const std::string& mentions) {
    std::ofstream(path, std::ios::binary) << content;
    try {
      dd::RecordingReader reader(path);
      dd::RecordedFrame read;
      while (reader.next(read)) {
      }
      ADD_FAILURE() << "accepted: " << mentions;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(mentions), std::string::npos) << error.what();
    }
  };
  expectRefused("hello world, not a recording", "not a physdbg recording");
  expectRefused(std::string("PHYSDBGR\x09\0\0\0", 12), "version 9");
  writeFrames(path, 2);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  expectRefused(bytes.substr(0, bytes.size() - 10), "truncated");
  EXPECT_THROW(dd::RecordingReader(tempPath("missing")), std::invalid_argument);
  fs::remove(path);
}

TEST(Recording, WriterRefusesMeshlessMeshesAndNegativeIndices) {
  const std::string path = tempPath("writer");
  dd::RecordingWriter writer(path);
  dd::RecordedFrame frame;
  frame.frame.meshes.push_back({dd::Vec3::Zero(), dd::Quat::Identity(), nullptr, {}});
  EXPECT_THROW(writer.write(frame), std::invalid_argument);
  frame.frame.meshes.clear();
  frame.index = -1;
  EXPECT_THROW(writer.write(frame), std::invalid_argument);
  EXPECT_THROW(dd::RecordingWriter("/dev/null/no/such/folder/file.rec"), std::runtime_error);
  fs::remove(path);
}

// --- Hostile input -----------------------------------------------------------

static_assert(std::endian::native == std::endian::little, "the byte patches below assume a little-endian host");

// What decoding may allocate: a few times the input (payloads, decoded items,
// the returned copies) plus small fixed costs.
std::size_t allocationBound(std::size_t fileBytes) { return 5 * fileBytes + 16 * 1024; }

// A version 1 file head: these tests build chunks by hand, and version 1 is still read.
std::string fileHead() { return std::string("PHYSDBGR\x01\0\0\0", 12); }

TEST(RecordingHostile, OversizeChunkIsRefusedBeforeAllocating) {
  // 24 bytes declaring a 16 GiB chunk, as a frame, as a skipped frame and under an unknown tag.
  for (const std::uint32_t tag : {2u, 1u, 99u}) {
    const std::string bytes = fileHead() + chunkHead(tag, std::uint64_t{16} << 30);
    ASSERT_EQ(bytes.size(), 24u);
    const Decoded decoded = decodeBytes(bytes, "oversize.rec");
    EXPECT_TRUE(decoded.refused);
    expectMentions(decoded.message, {"oversize.rec", "truncated chunk at byte offset 12: declares 17179869184 bytes, 0 remain"});
    EXPECT_LT(decoded.allocated, 4096u) << "tag " << tag;
  }
  const std::string path = tempPath("oversize");
  std::ofstream(path, std::ios::binary) << fileHead() + chunkHead(2, std::uint64_t{16} << 30) + "0123456789";
  dd::RecordingReader reader(path);
  dd::RecordedFrame read;
  try {
    reader.next(read, 5, 6);  // frame 5 only: the reader would seek past this chunk
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& error) {
    expectMentions(error.what(), {path, "declares 17179869184 bytes, 10 remain"});
  }
  fs::remove(path);
}

// A chunk within the file but over the 1 GiB limit (a sparse file, no disk used).
TEST(RecordingHostile, ChunkOverTheLimitIsRefusedInALongEnoughFile) {
  const std::string path = tempPath("limit");
  std::ofstream(path, std::ios::binary) << fileHead() + chunkHead(99, dd::maxChunkBytes + 1);
  fs::resize_file(path, 24 + dd::maxChunkBytes + 1);
  dd::RecordingReader reader(path);
  dd::RecordedFrame read;
  std::string message = "accepted";
  std::size_t allocated = 0;
  {
    const AllocationCount count;
    try {
      reader.next(read);
    } catch (const std::invalid_argument& error) {
      message = error.what();
    }
    allocated = count.bytes();
  }
  expectMentions(message, {path, "declares 1073741825 bytes, over the limit of 1073741824"});
  EXPECT_LT(allocated, 64u * 1024u);
  fs::remove(path);
}

TEST(RecordingHostile, EveryTruncationReadsFewerFramesOrIsRefused) {
  const std::string path = tempPath("prefix");
  const auto frames = writeFrames(path, 3);
  const std::string bytes = fileBytes(path);
  fs::remove(path);
  ASSERT_EQ(decodeBytes(bytes).frames, frames.size());
  int accepted = 0;
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const Decoded decoded = decodeBytes(bytes.substr(0, length), "prefix.rec");
    if (decoded.refused) {
      expectMentions(decoded.message, {"'prefix.rec'"});
    } else {
      EXPECT_LT(decoded.frames, frames.size()) << "prefix of " << length << " bytes";
      ++accepted;
    }
    EXPECT_LE(decoded.allocated, allocationBound(length)) << "prefix of " << length << " bytes";
    try {  // frames 0 and 1 are skipped by seeking
      dd::RecordingReader ranged(std::make_unique<std::istringstream>(bytes.substr(0, length)), "ranged.rec");
      dd::RecordedFrame read;
      while (ranged.next(read, 2, 3)) EXPECT_EQ(read.index, 2);
    } catch (const std::invalid_argument& error) {
      expectMentions(error.what(), {"'ranged.rec'"});
    }
  }
  EXPECT_EQ(accepted, 4);  // the bare header and the cuts after the mesh, frame 0 and frame 1
}

TEST(RecordingHostile, RandomByteFlipsAreDecodedOrRefusedWithinAnAllocationBound) {
  const std::string path = tempPath("flips");
  writeFrames(path, 3);
  const std::string bytes = fileBytes(path);
  fs::remove(path);
  std::mt19937 random(1234567);
  std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255), flips(1, 4);
  int refused = 0, decoded = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string flipped = bytes;
    for (int i = flips(random); i > 0; --i) flipped[position(random)] = static_cast<char>(byte(random));
    const Decoded outcome = decodeBytes(flipped);
    (outcome.refused ? refused : decoded) += 1;
    EXPECT_LE(outcome.allocated, allocationBound(bytes.size())) << "trial " << trial;
  }
  EXPECT_GT(refused, 100);
  EXPECT_GT(decoded, 100);
}

// What follows the characters of the last text of a frame without labels or
// bodies: its colour, its tag, and the empty label and body counts.
constexpr std::size_t afterLastText = 16 + 24 + 4 + 4;

// Grows the last text (of `length` characters) of a one-frame, mesh-free
// recording by `extra`, keeping its length field and the chunk size consistent.
std::string growLastText(std::string bytes, std::size_t length, const std::string& extra) {
  const std::size_t lengthAt = bytes.size() - afterLastText - length - 4;
  putNumber(bytes, lengthAt, static_cast<std::uint32_t>(numberAt<std::uint32_t>(bytes, lengthAt) + extra.size()));
  bytes.insert(bytes.size() - afterLastText, extra);
  putNumber(bytes, 16, numberAt<std::uint64_t>(bytes, 16) + extra.size());
  return bytes;
}

dd::RecordedFrame frameWithTexts(const std::vector<std::size_t>& lengths) {
  dd::RecordedFrame recorded;
  recorded.index = 4;
  for (const std::size_t length : lengths) recorded.frame.texts.push_back({1, 2, 2, std::string(length, 'a'), {}});
  return recorded;
}

TEST(RecordingHostile, OverLongTextsAreRefusedByWriterAndReader) {
  const std::size_t perText = dd::maxTextCharacters, perFrame = dd::maxFrameTextCharacters;
  ASSERT_EQ(perFrame % perText, 0u);
  const std::string path = tempPath("texts");
  dd::RecordingWriter writer(path);
  EXPECT_THROW(writer.write(frameWithTexts({perText + 1})), std::invalid_argument);
  std::vector<std::size_t> full(perFrame / perText, perText);  // exactly the frame's limit
  full.push_back(1);
  EXPECT_THROW(writer.write(frameWithTexts(full)), std::invalid_argument);
  fs::remove(path);

  const std::string longest = recordingBytes({frameWithTexts({perText})});
  ASSERT_EQ(decodeBytes(longest).frames, 1u);
  Decoded decoded = decodeBytes(growLastText(longest, perText, "b"), "text.rec");
  expectMentions(decoded.message, {"'text.rec'", "frame 4, texts: a text of 4097 characters, over the limit of 4096"});

  full.back() = 0;
  const std::string atLimit = recordingBytes({frameWithTexts(full)});
  ASSERT_EQ(decodeBytes(atLimit).frames, 1u);
  decoded = decodeBytes(growLastText(atLimit, 0, "b"), "frame.rec");
  expectMentions(decoded.message, {"'frame.rec'", "frame 4, 16385 characters of text in texts and labels, over the limit of 16384 per frame"});

  // A declared length of 4 Gi characters is refused before it is allocated.
  std::string huge = recordingBytes({frameWithTexts({0})});
  putNumber(huge, huge.size() - afterLastText - 4, std::uint32_t{0xffffffff});
  decoded = decodeBytes(huge);
  expectMentions(decoded.message, {"a text of 4294967295 characters"});
  EXPECT_LT(decoded.allocated, 64u * 1024u);
}

// The builder bounds its own output, whoever calls it: one text by length,
// a frame's vector by the geometry of maxFrameTextCharacters of the busiest glyph.
TEST(RecordingHostile, TextGeometryIsBoundedWhoeverCallsTheBuilder) {
  std::vector<physdbg::render::TextVertex> triangles;
  dd::Text text{0, 0, 1, std::string(dd::maxTextCharacters + 1, 'X'), {}};
  EXPECT_THROW(physdbg::render::appendText(text, triangles), std::invalid_argument);
  EXPECT_THROW(physdbg::render::appendTextOutline(text, triangles), std::invalid_argument);
  EXPECT_TRUE(triangles.empty());
  for (char character = 32; character < 127; ++character) {  // no glyph exceeds the bound the limit assumes
    std::vector<physdbg::render::TextVertex> glyph;
    physdbg::render::appendText({0, 0, 1, std::string(1, character), {}}, glyph);
    EXPECT_LE(glyph.size(), 11u * 6u) << character;
  }
  text.text.pop_back();  // 4096 of 'X', the busiest glyph
  triangles.reserve(physdbg::render::maxTextVertices());
  for (std::size_t i = 0; i < dd::maxFrameTextCharacters / dd::maxTextCharacters; ++i) {
    physdbg::render::appendTextOutline(text, triangles);
    physdbg::render::appendText(text, triangles);
  }
  EXPECT_EQ(triangles.size(), physdbg::render::maxTextVertices());
  EXPECT_THROW(physdbg::render::appendText({0, 0, 1, "X", {}}, triangles), std::invalid_argument);
  EXPECT_EQ(triangles.size(), physdbg::render::maxTextVertices());
}

dd::RecordedFrame plainFrame() {
  dd::RecordedFrame recorded;
  recorded.index = 7;
  const dd::Quat q = dd::Quat::Identity();
  const dd::Color c{0.5f, 0.5f, 0.5f, 1};
  dd::Frame& f = recorded.frame;
  f.boxes.push_back({{1, 2, 3}, q, {0.5, 0.5, 0.5}, c});
  f.spheres.push_back({{1, 2, 3}, q, 0.5, c});
  f.capsules.push_back({{1, 2, 3}, q, 0.5, 0.5, c});
  f.meshes.push_back({{1, 2, 3}, q, tetrahedron(), c});
  f.wireBoxes.push_back({{1, 2, 3}, q, {0.5, 0.5, 0.5}, c});
  f.lines.push_back({{0, 0, 0}, {1, 1, 1}, c});
  f.points.push_back({{1, 1, 1}, 6, c});
  f.arrows.push_back({{0, 0, 0}, {1, 1, 1}, c});
  f.texts.push_back({10, 10, 2, "hello", c});
  return recorded;
}

// One field, a valid marker value that occurs once in the encoded file, and a value to refuse.
struct BadValue {
  std::string mentions;
  std::function<void(dd::RecordedFrame&, double)> set;
  bool isFloat;
  double marker, bad;
};

std::vector<BadValue> badValues() {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  auto withVertex = [](dd::RecordedFrame& r, double v) {
    auto mesh = std::make_shared<dd::TriangleMesh>(*tetrahedron());
    mesh->vertices[1].x() = static_cast<float>(v);
    r.frame.meshes[0].mesh = mesh;
  };
  return {
      {"frame 7, view: eye", [](auto& r, double v) { r.view.eye.x() = v; }, false, 7777.25, nan},
      {"frame 7, view: vertical field of view", [](auto& r, double v) { r.view.fovYDegrees = v; }, false, 33.125, 0},
      {"frame 7, solid boxes item 0: centre", [](auto& r, double v) { r.frame.boxes[0].center.y() = v; }, false, 7777.25, nan},
      {"frame 7, solid spheres item 0: radius", [](auto& r, double v) { r.frame.spheres[0].radius = v; }, false, 0.875, -1},
      {"frame 7, capsules item 0: half height", [](auto& r, double v) { r.frame.capsules[0].halfHeight = v; }, false, 0.875, inf},
      {"frame 7, solid meshes item 0: orientation", [](auto& r, double v) { r.frame.meshes[0].orientation = dd::Quat(v, 0, 0, 0); }, false, 0.875, 1e300},
      {"frame 7, wire boxes item 0: orientation", [](auto& r, double v) { r.frame.wireBoxes[0].orientation = dd::Quat(v, 0, 0, 0); }, false, 0.875, 0},
      {"frame 7, lines item 0: colour", [](auto& r, double v) { r.frame.lines[0].color.g = static_cast<float>(v); }, true, 0.8125, nan},
      {"frame 7, points item 0: size in pixels", [](auto& r, double v) { r.frame.points[0].sizePixels = static_cast<float>(v); }, true, 6.125, 1e9},
      {"frame 7, points item 0: size in pixels", [](auto& r, double v) { r.frame.points[0].sizePixels = static_cast<float>(v); }, true, 6.125, -1},
      {"frame 7, points item 0: position", [](auto& r, double v) { r.frame.points[0].position.z() = v; }, false, 7777.25, 1e13},
      {"frame 7, arrows item 0: end", [](auto& r, double v) { r.frame.arrows[0].to.z() = v; }, false, 7777.25, -inf},
      {"frame 7, texts item 0: scale", [](auto& r, double v) { r.frame.texts[0].scale = static_cast<float>(v); }, true, 2.3, nan},
      {"frame 7, texts item 0: scale", [](auto& r, double v) { r.frame.texts[0].scale = static_cast<float>(v); }, true, 2.3, 0},
      {"frame 7, texts item 0: x", [](auto& r, double v) { r.frame.texts[0].x = static_cast<float>(v); }, true, 7777.25, inf},
      {"mesh 77: vertex", withVertex, true, 0.8125, nan},
  };
}

std::string encodedValue(const BadValue& value, double number) {
  return value.isFloat ? bitsOf(static_cast<float>(number)) : bitsOf(number);
}

TEST(RecordingHostile, NonFiniteAndAbsurdValuesAreRefusedNamingFrameAndList) {
  const std::string path = tempPath("values");
  for (const BadValue& value : badValues()) {
    SCOPED_TRACE(value.mentions + " = " + std::to_string(value.bad));
    dd::RecordedFrame recorded = plainFrame();
    value.set(recorded, value.marker);
    std::string bytes = recordingBytes({recorded});
    ASSERT_EQ(decodeBytes(bytes).frames, 1u);
    const std::string marker = encodedValue(value, value.marker);
    const std::size_t at = bytes.find(marker);
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(bytes.find(marker, at + 1), std::string::npos) << "marker not unique";
    bytes.replace(at, marker.size(), encodedValue(value, value.bad));
    const Decoded decoded = decodeBytes(bytes, "values.rec");
    EXPECT_TRUE(decoded.refused);
    expectMentions(decoded.message, {"'values.rec'", value.mentions});

    value.set(recorded, value.bad);
    dd::RecordingWriter writer(path);
    try {
      writer.write(recorded);
      ADD_FAILURE() << "writer accepted it";
    } catch (const std::invalid_argument& error) {
      expectMentions(error.what(), {path, value.mentions});
    }
  }
  fs::remove(path);
}

TEST(RecordingHostile, CorruptStructureIsRefusedWithItsPlace) {
  const std::string frame = recordingBytes({plainFrame()});
  const std::size_t meshChunkBytes = 12 + numberAt<std::uint64_t>(frame, 16);
  const std::string meshChunk = frame.substr(12, meshChunkBytes);
  auto refusal = [](const std::string& bytes) { return decodeBytes(bytes, "corrupt.rec").message; };
  // A mesh defined twice, an index out of range, a frame index over 2^31 - 1, a short frame chunk.
  expectMentions(refusal(fileHead() + meshChunk + meshChunk), {"defines mesh 77 a second time"});
  std::string badIndex = fileHead() + meshChunk;
  putNumber(badIndex, badIndex.size() - 4, std::uint32_t{4});
  expectMentions(refusal(badIndex), {"mesh 77: index 4 out of range"});
  expectMentions(refusal(fileHead() + chunkHead(2, 4) + bitsOf(std::uint32_t{0x80000000})),
                 {"frame index 2147483648 is over 2147483647"});
  expectMentions(refusal(fileHead() + chunkHead(2, 2) + "ab"), {"frame chunk at byte offset 12 is 2 bytes"});
  expectMentions(refusal(fileHead() + "abc"), {"truncated chunk header at byte offset 12: 12 bytes needed, 3 remain"});
  EXPECT_EQ(decodeBytes(fileHead() + chunkHead(99, 3) + "xyz").frames, 0u);  // unknown tags are skipped
}

}  // namespace
