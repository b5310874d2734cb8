// The recording format: every primitive kind survives a round trip bit for
// bit, frame ranges skip frames, bad files are refused with clear messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "debugdraw/recording.h"

namespace {

namespace dd = physdbg::debugdraw;
namespace fs = std::filesystem;

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("physdbg-recording-" + std::to_string(::getpid()) + "-" + name)).string();
}

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
    f.boxes.push_back({randomVector(random), q, randomVector(random), randomColor(random)});
    f.spheres.push_back({randomVector(random), q, 0.1 + i, randomColor(random)});
    f.capsules.push_back({randomVector(random), q, 0.2, 0.3 + i, randomColor(random)});
    f.meshes.push_back({randomVector(random), q, mesh, randomColor(random)});
    f.wireBoxes.push_back({randomVector(random), q, randomVector(random), randomColor(random)});
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

}  // namespace
