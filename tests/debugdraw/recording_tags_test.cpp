// Recording format version 2: primitive tags, world-anchored labels and body
// state survive a round trip exactly, so `physdbg replay` can choose layers
// and bodies with no engine. Version 1 files still read (default tags); newer
// versions and values beyond the new limits are refused, by readers and writers.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <tuple>

#include "debugdraw/recording.h"
#include "recording_test_support.h"
#include "tests/support/visual_test_support.h"

namespace {

using namespace physdbg::recordingtesting;
using dd::Layer;

std::shared_ptr<const dd::TriangleMesh> triangle() {
  auto mesh = std::make_shared<dd::TriangleMesh>();
  mesh->id = 5;
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->indices = {0, 1, 2};
  return mesh;
}

// A distinct, non-default tag per list so a tag read into the wrong list shows.
dd::Tag tagFor(Layer layer, int seed) {
  dd::Tag tag = dd::tagOf(layer, seed, seed + 1);
  tag.node = seed + 2;
  tag.parent = seed + 3;
  tag.depth = seed % 5;
  return tag;
}

dd::BodyInfo crate(int index) {
  dd::BodyInfo body;
  body.index = index;
  body.name = "crate " + std::to_string(index);
  body.position = {1.5, -2.25, 3e6};
  body.linearVelocity = {0.125, -9.81, 4};
  body.angularVelocity = {-1, 0.5, 0.25};
  body.boundsMin = {1, -2.75, 3e6 - 0.5};
  body.boundsMax = {2, -1.75, 3e6 + 0.5};
  body.contacts = 3;
  body.treeLeaf = 17;
  body.treeParent = 9;
  body.isStatic = index % 2 == 0;
  body.asleep = index % 3 == 0;
  body.absent = index == 1;
  return body;
}

// One item in every list, each with its own tag, plus two labels and three bodies.
dd::RecordedFrame everyList() {
  dd::RecordedFrame recorded;
  recorded.index = 7;
  const dd::Quat q = dd::Quat(0.3, -0.5, 0.7, 0.1).normalized();
  const dd::Color c{0.25f, 0.5f, 0.75f, 1};
  dd::Frame& f = recorded.frame;
  f.boxes.push_back({{1, 2, 3}, q, {0.5, 0.5, 0.5}, c, tagFor(Layer::Shapes, 10)});
  f.spheres.push_back({{1, 2, 3}, q, 0.5, c, tagFor(Layer::Shapes, 20)});
  f.capsules.push_back({{1, 2, 3}, q, 0.5, 0.25, c, tagFor(Layer::Shapes, 30)});
  f.meshes.push_back({{1, 2, 3}, q, triangle(), c, tagFor(Layer::Shapes, 40)});
  f.wireBoxes.push_back({{1, 2, 3}, q, {0.5, 1, 2}, c, tagFor(Layer::Tree, 50)});
  f.lines.push_back({{0, 0, 0}, {1, 1, 1}, c, tagFor(Layer::Grid, 60)});
  f.points.push_back({{1, 1, 1}, 6, c, tagFor(Layer::Contacts, 70)});
  f.arrows.push_back({{0, 0, 0}, {1, 1, 1}, c, tagFor(Layer::Impulses, 80)});
  f.texts.push_back({10, 10, 2, "overlay", c, tagFor(Layer::Overlay, 90)});
  f.labels.push_back({{1, 2.5, 3}, 1.5f, "crate 0", c, tagFor(Layer::Overlay, 0)});
  f.labels.push_back({{-4, 0, 1e6}, 0.75f, "", {1, 0, 0, 0.5f}, {}});
  for (int i = 0; i < 3; ++i) f.bodies.push_back(crate(i));
  f.bodies[2].name.clear();
  f.bodies[2].treeLeaf = f.bodies[2].treeParent = -1;
  return recorded;
}

template <typename Item>
std::vector<dd::Tag> tagsOf(const std::vector<Item>& items) {
  std::vector<dd::Tag> tags;
  for (const Item& item : items) tags.push_back(item.tag);
  return tags;
}

void expectSameLabel(const dd::Label& a, const dd::Label& b) {
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.text, b.text);
  EXPECT_EQ(std::make_tuple(a.color.r, a.color.g, a.color.b, a.color.a),
            std::make_tuple(b.color.r, b.color.g, b.color.b, b.color.a));
  EXPECT_EQ(a.tag, b.tag);
}

void expectSameBody(const dd::BodyInfo& a, const dd::BodyInfo& b) {
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.linearVelocity, b.linearVelocity);
  EXPECT_EQ(a.angularVelocity, b.angularVelocity);
  EXPECT_EQ(a.boundsMin, b.boundsMin);
  EXPECT_EQ(a.boundsMax, b.boundsMax);
  EXPECT_EQ(std::make_tuple(a.contacts, a.treeLeaf, a.treeParent, a.isStatic, a.asleep, a.absent),
            std::make_tuple(b.contacts, b.treeLeaf, b.treeParent, b.isStatic, b.asleep, b.absent));
}

// Tags, labels and bodies: the other fields are compared by recording_format_test.
void expectSameTaggedFrame(const dd::Frame& a, const dd::Frame& b) {
  EXPECT_EQ(tagsOf(a.boxes), tagsOf(b.boxes));
  EXPECT_EQ(tagsOf(a.spheres), tagsOf(b.spheres));
  EXPECT_EQ(tagsOf(a.capsules), tagsOf(b.capsules));
  EXPECT_EQ(tagsOf(a.meshes), tagsOf(b.meshes));
  EXPECT_EQ(tagsOf(a.wireBoxes), tagsOf(b.wireBoxes));
  EXPECT_EQ(tagsOf(a.lines), tagsOf(b.lines));
  EXPECT_EQ(tagsOf(a.points), tagsOf(b.points));
  EXPECT_EQ(tagsOf(a.arrows), tagsOf(b.arrows));
  EXPECT_EQ(tagsOf(a.texts), tagsOf(b.texts));
  ASSERT_EQ(a.labels.size(), b.labels.size());
  for (std::size_t i = 0; i < a.labels.size(); ++i) expectSameLabel(a.labels[i], b.labels[i]);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) expectSameBody(a.bodies[i], b.bodies[i]);
}

dd::RecordingReader readerOf(const std::string& bytes, const std::string& name) {
  return dd::RecordingReader(std::make_unique<std::istringstream>(bytes), name);
}

TEST(RecordingTags, EveryListWithTagsLabelsAndBodiesRoundTripsExactly) {
  const dd::RecordedFrame written = everyList();
  const std::string bytes = recordingBytes({written});
  dd::RecordingReader reader = readerOf(bytes, "tags.rec");
  EXPECT_EQ(reader.version(), 4u);
  dd::RecordedFrame read;
  ASSERT_TRUE(reader.next(read));
  EXPECT_EQ(read.index, 7);
  EXPECT_EQ(read.frame.primitiveCount(), written.frame.primitiveCount());
  expectSameTaggedFrame(written.frame, read.frame);
  EXPECT_FALSE(reader.next(read));
  EXPECT_EQ(recordingBytes({read}), bytes);  // nothing else was lost either
}

// Little-endian version 1 bytes, written the way the version 1 writer did.
class Version1Bytes {
 public:
  std::string bytes;
  Version1Bytes& u32(std::uint32_t value) { return add(value); }
  Version1Bytes& f32(float value) { return add(value); }
  Version1Bytes& f64(double value) { return add(value); }
  Version1Bytes& vec3(double x, double y, double z) { return f64(x).f64(y).f64(z); }
  Version1Bytes& identity() { return f64(1).f64(0).f64(0).f64(0); }
  Version1Bytes& color() { return f32(0.5f).f32(0.25f).f32(1).f32(1); }
  Version1Bytes& text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    bytes += s;
    return *this;
  }

 private:
  template <typename Number>
  Version1Bytes& add(Number value) {
    bytes += bitsOf(value);
    return *this;
  }
};

// A version 1 file: one mesh chunk, then frame 3 with one item in each of the nine lists.
std::string version1File() {
  Version1Bytes mesh;
  mesh.u32(5).u32(0).u32(3).f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).u32(3).u32(0).u32(1).u32(2);
  Version1Bytes frame;
  frame.u32(3).vec3(0, 0, 10).vec3(0, 0, 0).vec3(0, 1, 0).f64(45).u32(0).f64(10);
  frame.u32(1).vec3(1, 2, 3).identity().vec3(0.5, 0.5, 0.5).color();  // solid box
  frame.u32(1).vec3(1, 2, 3).identity().f64(0.5).color();             // sphere
  frame.u32(1).vec3(1, 2, 3).identity().f64(0.5).f64(0.25).color();   // capsule
  frame.u32(1).vec3(1, 2, 3).identity().u32(5).u32(0).color();        // mesh 5 (u64 id)
  frame.u32(1).vec3(1, 2, 3).identity().vec3(0.5, 1, 2).color();      // wire box
  frame.u32(1).vec3(0, 0, 0).vec3(1, 1, 1).color();                   // line
  frame.u32(1).vec3(1, 1, 1).f32(6).color();                          // point
  frame.u32(1).vec3(0, 0, 0).vec3(1, 1, 1).color();                   // arrow
  frame.u32(1).f32(10).f32(10).f32(2).text("step 3").color();         // text
  return std::string("PHYSDBGR\x01\0\0\0", 12) + chunkHead(1, mesh.bytes.size()) + mesh.bytes +
         chunkHead(2, frame.bytes.size()) + frame.bytes;
}

TEST(RecordingTags, Version1FilesStillReadWithDefaultTags) {
  dd::RecordingReader reader = readerOf(version1File(), "old.rec");
  EXPECT_EQ(reader.version(), 1u);
  dd::RecordedFrame read;
  ASSERT_TRUE(reader.next(read));
  EXPECT_EQ(read.index, 3);
  const dd::Frame& f = read.frame;
  EXPECT_EQ(f.primitiveCount(), 9u);
  EXPECT_TRUE(f.labels.empty());
  EXPECT_TRUE(f.bodies.empty());
  const std::vector<dd::Tag> untagged{dd::Tag{}};
  for (const auto& tags : {tagsOf(f.boxes), tagsOf(f.spheres), tagsOf(f.capsules), tagsOf(f.meshes),
                           tagsOf(f.wireBoxes), tagsOf(f.lines), tagsOf(f.points), tagsOf(f.arrows), tagsOf(f.texts)})
    EXPECT_EQ(tags, untagged);
  EXPECT_EQ(f.capsules[0].halfHeight, 0.25);
  EXPECT_EQ(f.meshes[0].mesh->indices.size(), 3u);
  EXPECT_EQ(f.wireBoxes[0].halfExtents, dd::Vec3(0.5, 1, 2));
  EXPECT_EQ(f.texts[0].text, "step 3");
  EXPECT_EQ(f.texts[0].color.g, 0.25f);
  EXPECT_FALSE(reader.next(read));
  // Written again, it is a version 4 file with the same primitives.
  const std::vector<dd::RecordedFrame> again = dd::readRecordingBytes(recordingBytes({read}), "again.rec");
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].frame.primitiveCount(), 9u);
}

// replay still draws a version 1 file as recorded, and says why it cannot
// choose layers, bodies or a camera in one.
TEST(RecordingTags, ReplayOfAVersion1FileDrawsItAndRefusesViewChoices) {
  physdbg::visualtesting::ScratchFolder folder;
  std::ofstream(folder / "old.rec", std::ios::binary) << version1File();
  using physdbg::visualtesting::runPhysdbg;
  const auto plain = runPhysdbg("replay " + (folder / "old.rec") + " --size 64x48 -o " + (folder / "plain"));
  EXPECT_EQ(plain.exitCode, 0) << plain.output;
  for (const char* option : {"--layers shapes", "--highlight 0", "--labels", "--eye 1,2,3", "--tree-depth 0:1 --layers tree"}) {
    const auto refused =
        runPhysdbg("replay " + (folder / "old.rec") + " --size 64x48 " + option + " -o " + (folder / "chosen"));
    EXPECT_EQ(refused.exitCode, 2) << option << "\n" << refused.output;
    expectMentions(refused.output, {"old.rec", "version 1", "recorded again"});
  }
}

TEST(RecordingTags, NewerVersionsAreRefusedNamingTheVersion) {
  std::string bytes = recordingBytes({everyList()});
  putNumber(bytes, 8, std::uint32_t{5});
  const Decoded decoded = decodeBytes(bytes, "future.rec");
  EXPECT_TRUE(decoded.refused);
  expectMentions(decoded.message, {"'future.rec'", "version 5", "versions 1 to 4"});
  putNumber(bytes, 8, std::uint32_t{0});
  expectMentions(decodeBytes(bytes, "zero.rec").message, {"'zero.rec'", "version 0"});
}

// The absent flag is version 3's: the same bytes labelled version 2 are
// refused at the body that sets it (crate 1), saying which version has it.
TEST(RecordingTags, AbsentFlagIsRefusedInAVersion2File) {
  dd::RecordedFrame frame = everyList();
  frame.shownLayers.bits &= ~static_cast<std::uint32_t>(Layer::Mesh);  // version 4's bit
  std::string bytes = recordingBytes({frame});
  putNumber(bytes, 8, std::uint32_t{2});
  const Decoded decoded = decodeBytes(bytes, "old.rec");
  EXPECT_TRUE(decoded.refused);
  expectMentions(decoded.message, {"'old.rec'", "bodies item 1", "flags 4", "version 3"});
}

// One field of everyList(), a valid marker value that occurs once in the
// encoded file, and a value to refuse: readers and writers must both refuse it.
enum class Encoding { f64, f32, i32, u32 };

struct BadField {
  std::string mentions;
  std::function<void(dd::RecordedFrame&, double)> set;
  Encoding encoding;
  double marker, bad;
};

std::string encoded(Encoding encoding, double value) {
  switch (encoding) {
    case Encoding::f64: return bitsOf(value);
    case Encoding::f32: return bitsOf(static_cast<float>(value));
    case Encoding::i32: return bitsOf(static_cast<std::int32_t>(value));
    case Encoding::u32: return bitsOf(static_cast<std::uint32_t>(value));
  }
  return {};
}

std::vector<BadField> tagFields() {
  auto i32 = [](double v) { return static_cast<std::int32_t>(v); };
  return {
      {"frame 7, lines item 0: tag layer 3 is neither 0 nor one known layer bit",
       [](auto& r, double v) { r.frame.lines[0].tag.layer = static_cast<std::uint32_t>(v); }, Encoding::u32, 0x80, 3},
      {"frame 7, points item 0: tag layer 8192 is neither 0 nor one known layer bit",
       [](auto& r, double v) { r.frame.points[0].tag.layer = static_cast<std::uint32_t>(v); }, Encoding::u32, 0x80, 8192},
      {"frame 7, solid boxes item 0: tag body -2 is below -1",
       [=](auto& r, double v) { r.frame.boxes[0].tag.body = i32(v); }, Encoding::i32, 654321, -2},
      {"frame 7, arrows item 0: tag other body -7 is below -1",
       [=](auto& r, double v) { r.frame.arrows[0].tag.otherBody = i32(v); }, Encoding::i32, 654321, -7},
      {"frame 7, wire boxes item 0: tag node -2 is below -1",
       [=](auto& r, double v) { r.frame.wireBoxes[0].tag.node = i32(v); }, Encoding::i32, 654321, -2},
      {"frame 7, capsules item 0: tag parent -100 is below -1",
       [=](auto& r, double v) { r.frame.capsules[0].tag.parent = i32(v); }, Encoding::i32, 654321, -100},
      {"frame 7, texts item 0: tag depth -2147483648 is below -1",
       [=](auto& r, double v) { r.frame.texts[0].tag.depth = i32(v); }, Encoding::i32, 654321, -2147483648.0},
      {"frame 7, labels item 0: tag body -3 is below -1",
       [=](auto& r, double v) { r.frame.labels[0].tag.body = i32(v); }, Encoding::i32, 654321, -3},
  };
}

std::vector<BadField> labelAndBodyFields() {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  auto i32 = [](double v) { return static_cast<std::int32_t>(v); };
  auto f32 = [](double v) { return static_cast<float>(v); };
  return {
      {"frame 7, labels item 0: position", [](auto& r, double v) { r.frame.labels[0].position.y() = v; }, Encoding::f64, 7777.25, nan},
      {"frame 7, labels item 0: position", [](auto& r, double v) { r.frame.labels[0].position.z() = v; }, Encoding::f64, 7777.25, -1e13},
      {"frame 7, labels item 0: scale", [=](auto& r, double v) { r.frame.labels[0].scale = f32(v); }, Encoding::f32, 2.3, 0},
      {"frame 7, labels item 0: scale", [=](auto& r, double v) { r.frame.labels[0].scale = f32(v); }, Encoding::f32, 2.3, 1e9},
      {"frame 7, labels item 0: colour", [=](auto& r, double v) { r.frame.labels[0].color.b = f32(v); }, Encoding::f32, 0.8125, inf},
      {"frame 7, bodies item 1: index -1 is below 0", [=](auto& r, double v) { r.frame.bodies[1].index = i32(v); }, Encoding::i32, 654321, -1},
      {"frame 7, bodies item 0: position", [](auto& r, double v) { r.frame.bodies[0].position.x() = v; }, Encoding::f64, 7777.25, inf},
      {"frame 7, bodies item 0: linear velocity", [](auto& r, double v) { r.frame.bodies[0].linearVelocity.y() = v; }, Encoding::f64, 7777.25, nan},
      {"frame 7, bodies item 2: angular velocity", [](auto& r, double v) { r.frame.bodies[2].angularVelocity.z() = v; }, Encoding::f64, 7777.25, 2e12},
      {"frame 7, bodies item 0: bounds max", [](auto& r, double v) { r.frame.bodies[0].boundsMax.x() = v; }, Encoding::f64, 7777.25, nan},
      {"frame 7, bodies item 0: bounds x: min 1 is above max 0.5", [](auto& r, double v) { r.frame.bodies[0].boundsMax.x() = v; }, Encoding::f64, 7777.25, 0.5},
      {"frame 7, bodies item 1: contacts -1 is below 0", [=](auto& r, double v) { r.frame.bodies[1].contacts = i32(v); }, Encoding::i32, 654321, -1},
      {"frame 7, bodies item 1: tree leaf -2 is below -1", [=](auto& r, double v) { r.frame.bodies[1].treeLeaf = i32(v); }, Encoding::i32, 654321, -2},
      {"frame 7, bodies item 1: tree parent -9 is below -1", [=](auto& r, double v) { r.frame.bodies[1].treeParent = i32(v); }, Encoding::i32, 654321, -9},
  };
}

void expectRefusedByReaderAndWriter(const BadField& field) {
  SCOPED_TRACE(field.mentions + " = " + std::to_string(field.bad));
  dd::RecordedFrame recorded = everyList();
  field.set(recorded, field.marker);
  std::string bytes = recordingBytes({recorded});
  ASSERT_EQ(decodeBytes(bytes).frames, 1u);
  const std::string marker = encoded(field.encoding, field.marker);
  const std::size_t at = bytes.find(marker);
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(bytes.find(marker, at + 1), std::string::npos) << "marker not unique";
  bytes.replace(at, marker.size(), encoded(field.encoding, field.bad));
  const Decoded decoded = decodeBytes(bytes, "limits.rec");
  EXPECT_TRUE(decoded.refused);
  expectMentions(decoded.message, {"'limits.rec'", field.mentions});

  field.set(recorded, field.bad);
  const std::string path = tempPath("limits");
  dd::RecordingWriter writer(path);
  try {
    writer.write(recorded);
    ADD_FAILURE() << "writer accepted it";
  } catch (const std::invalid_argument& error) {
    expectMentions(error.what(), {path, "cannot write", field.mentions});
  }
  fs::remove(path);
}

TEST(RecordingTags, TagsOutsideTheirLimitsAreRefusedByReaderAndWriter) {
  for (const BadField& field : tagFields()) expectRefusedByReaderAndWriter(field);
}

TEST(RecordingTags, LabelsAndBodiesOutsideTheirLimitsAreRefusedByReaderAndWriter) {
  for (const BadField& field : labelAndBodyFields()) expectRefusedByReaderAndWriter(field);
}

// The body flags byte is the last byte of a frame whose last list is bodies:
// only bits 0 (static), 1 (asleep) and 2 (absent) are defined.
TEST(RecordingTags, UnknownBodyFlagsAreRefused) {
  std::string bytes = recordingBytes({everyList()});
  ASSERT_EQ(bytes.back(), 1);  // body 2: static, awake
  bytes.back() = 7;
  ASSERT_EQ(decodeBytes(bytes).frames, 1u);
  bytes.back() = 8;
  expectMentions(decodeBytes(bytes, "flags.rec").message,
                 {"'flags.rec'", "frame 7, bodies item 2: flags 8 set bits other than 0 (static), 1 (asleep) and 2 (absent)"});
}

dd::RecordedFrame oneLabel(std::size_t characters) {
  dd::RecordedFrame recorded;
  recorded.index = 4;
  recorded.frame.labels.push_back({{0, 0, 0}, 1, std::string(characters, 'a'), {}, {}});
  return recorded;
}

// Frame 4 holding one label or one body: where its string's length field is.
constexpr std::size_t afterLabelText = 16 + 24 + 4;  // colour, tag, empty body count
constexpr std::size_t afterBodyName = 5 * 24 + 3 * 4 + 1;

TEST(RecordingTags, OverLongLabelsAndNamesAreRefusedBeforeAllocating) {
  const std::string path = tempPath("long");
  dd::RecordingWriter writer(path);
  try {
    writer.write(oneLabel(dd::maxTextCharacters + 1));
    ADD_FAILURE() << "writer accepted a long label";
  } catch (const std::invalid_argument& error) {
    expectMentions(error.what(), {path, "frame 4, labels item 0: a text of 4097 characters, over the limit of 4096"});
  }
  dd::RecordedFrame named;
  named.index = 4;
  named.frame.bodies.push_back(crate(0));
  named.frame.bodies[0].name.assign(dd::maxTextCharacters + 1, 'n');
  try {
    writer.write(named);
    ADD_FAILURE() << "writer accepted a long name";
  } catch (const std::invalid_argument& error) {
    expectMentions(error.what(), {path, "frame 4, bodies item 0: a name of 4097 characters"});
  }
  fs::remove(path);

  // Declared lengths of 4 Gi characters, refused before they are allocated.
  std::string label = recordingBytes({oneLabel(0)});
  putNumber(label, label.size() - afterLabelText - 4, std::uint32_t{0xffffffff});
  Decoded decoded = decodeBytes(label, "label.rec");
  expectMentions(decoded.message, {"'label.rec'", "frame 4, labels: a text of 4294967295 characters"});
  EXPECT_LT(decoded.allocated, 64u * 1024u);
  named.frame.bodies[0].name.clear();
  std::string body = recordingBytes({named});
  putNumber(body, body.size() - afterBodyName - 4, std::uint32_t{dd::maxTextCharacters + 1});
  decoded = decodeBytes(body, "name.rec");
  expectMentions(decoded.message, {"'name.rec'", "frame 4, bodies: a name of 4097 characters, over the limit of 4096"});
  EXPECT_LT(decoded.allocated, 64u * 1024u);
}

// Labels are drawn as glyphs like texts, so they share the frame's character budget.
TEST(RecordingTags, TextsAndLabelsShareTheFrameCharacterLimit) {
  dd::RecordedFrame recorded = oneLabel(dd::maxTextCharacters);
  for (std::size_t total = dd::maxTextCharacters; total < dd::maxFrameTextCharacters; total += dd::maxTextCharacters)
    recorded.frame.texts.push_back({0, 0, 1, std::string(dd::maxTextCharacters, 't'), {}, {}});
  recorded.frame.labels.push_back({{0, 0, 0}, 1, "", {}, {}});  // the last label: one character more is too many
  std::string bytes = recordingBytes({recorded});
  ASSERT_EQ(decodeBytes(bytes).frames, 1u);
  const std::string limit = "16385 characters of text in texts and labels, over the limit of 16384 per frame";

  const std::size_t lengthAt = bytes.size() - afterLabelText - 4;  // grown by one, chunk size kept consistent
  putNumber(bytes, lengthAt, std::uint32_t{1});
  bytes.insert(bytes.size() - afterLabelText, "b");
  putNumber(bytes, 16, numberAt<std::uint64_t>(bytes, 16) + 1);
  expectMentions(decodeBytes(bytes, "budget.rec").message, {"'budget.rec'", "frame 4, " + limit});

  recorded.frame.labels.back().text = "x";
  const std::string path = tempPath("budget");
  dd::RecordingWriter writer(path);
  try {
    writer.write(recorded);
    ADD_FAILURE() << "writer accepted it";
  } catch (const std::invalid_argument& error) {
    expectMentions(error.what(), {path, "frame 4, " + limit});
  }
  fs::remove(path);
}

TEST(RecordingTags, BodyCountOverTheLimitIsRefusedBeforeAllocating) {
  std::string bytes = recordingBytes({oneLabel(0)});
  putNumber(bytes, bytes.size() - 4, std::uint32_t{dd::maxListItems + 1});
  Decoded decoded = decodeBytes(bytes, "count.rec");
  expectMentions(decoded.message, {"'count.rec'", "frame 4, bodies: 16777217 items, over the limit of 16777216"});
  EXPECT_LT(decoded.allocated, 64u * 1024u);
  putNumber(bytes, bytes.size() - 4, dd::maxListItems);  // within the limit, but not in the chunk
  decoded = decodeBytes(bytes, "count.rec");
  expectMentions(decoded.message, {"frame 4, bodies: 16777216 items of 141 bytes run past the end of the chunk"});
  EXPECT_LT(decoded.allocated, 64u * 1024u);
}

// Cut inside the labels or the bodies with the chunk's declared size cut to
// match: the frame decoder itself meets the end, and names the list.
TEST(RecordingTags, TruncationInsideLabelsOrBodiesNamesTheList) {
  dd::RecordedFrame recorded = oneLabel(5);
  recorded.frame.bodies.push_back(crate(1));
  const std::string bytes = recordingBytes({recorded});
  const std::size_t bodiesAt = bytes.size() - 4 - (4 + 4 + crate(1).name.size() + afterBodyName);
  const std::size_t labelsAt = bodiesAt - 4 - (24 + 4 + 4 + 5 + afterLabelText - 4);
  for (std::size_t length = labelsAt; length < bytes.size(); ++length) {
    SCOPED_TRACE("cut at byte " + std::to_string(length));
    const Decoded cutFile = decodeBytes(bytes.substr(0, length), "cut.rec");
    EXPECT_TRUE(cutFile.refused);
    expectMentions(cutFile.message, {"'cut.rec'", "truncated chunk at byte offset 12"});
    std::string cutChunk = bytes.substr(0, length);
    putNumber(cutChunk, 16, numberAt<std::uint64_t>(cutChunk, 16) - (bytes.size() - length));
    const Decoded decoded = decodeBytes(cutChunk, "cut.rec");
    EXPECT_TRUE(decoded.refused);
    expectMentions(decoded.message, {"'cut.rec'", length < bodiesAt ? "frame 4, labels: " : "frame 4, bodies: "});
    EXPECT_LE(decoded.allocated, 5 * length + 16 * 1024);
  }
}

// The mesh layer's bit is version 4's: a version 3 file that shows it is refused.
TEST(RecordingTags, MeshLayerIsRefusedInAVersion3File) {
  dd::RecordedFrame frame = everyList();
  frame.shownLayers.bits |= static_cast<std::uint32_t>(Layer::Mesh);
  std::string bytes = recordingBytes({frame});
  putNumber(bytes, 8, std::uint32_t{3});
  const Decoded decoded = decodeBytes(bytes, "v3.rec");
  EXPECT_TRUE(decoded.refused);
  expectMentions(decoded.message, {"'v3.rec'", "shown layers"});
}

}  // namespace
