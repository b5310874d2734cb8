// Scene files written by someone else: each class of hostile input is refused
// with a short message naming the file and the key, before anything large is
// allocated, and never with anything but SceneError.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "engine/world.h"
#include "scenes/scene.h"
#include "scenes/scene_limits.h"

namespace physdbg {
namespace {

std::string errorOf(const std::string& text) {
  try {
    const SceneDescription scene = parseScene(text, "hostile.json");
    buildWorld(scene);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

void expectRefused(const std::string& text, const std::string& key, const std::string& what) {
  const std::string message = errorOf(text);
  ASSERT_FALSE(message.empty()) << "accepted: " << text.substr(0, 200);
  EXPECT_EQ(message.rfind("hostile.json: ", 0), 0u) << message;
  EXPECT_NE(message.find(key), std::string::npos) << message;
  EXPECT_NE(message.find(what), std::string::npos) << message;
  EXPECT_LT(message.size(), 400u) << "messages quote excerpts, not whole values";
}

const std::string sphere = R"("shape": {"sphere": {"radius": 0.5}})";

std::string withBody(const std::string& keys) { return R"({"bodies": [{)" + sphere + keys + "}]}"; }

TEST(SceneHostileInput, DeepNestingIsRefusedBeforeParsing) {
  const int depth = 70'000;
  const std::string text = R"({"bodies": [], "camera": )" + std::string(depth, '[') + std::string(depth, ']') + "}";
  expectRefused(text, "line 1", "nested deeper than 32 levels");
  // Nesting that a real scene uses is fine.
  EXPECT_EQ(errorOf(R"({"bodies": [{"shape": {"convex": {"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}}}]})"), "");
}

TEST(SceneHostileInput, LongStringsAreQuotedAsExcerpts) {
  const std::string huge(5'000'000, 'x');
  expectRefused(R"({"bodies": [], "steps": ")" + huge + "\"}", "steps", "(5000000 bytes)");
  expectRefused(R"({"bodies": [], ")" + huge + "\": 1}", "unknown key", "(5000000 bytes)");
  expectRefused(R"({"bodies": [{"shape": {")" + huge + "\": {}}}]}", "bodies[0].shape", "unknown shape");
  expectRefused(R"({"bodies": [], "solver": {"kind": ")" + huge + "\"}}", "solver.kind", "(5000000 bytes)");
  expectRefused(R"({"bodies": [], "layers": "shapes,)" + huge + "\"}", "layers", "unknown layer");
  expectRefused(R"({"bodies": [], "name": ")" + huge, "malformed JSON", "...");
}

TEST(SceneHostileInput, RepeatCountsAreBoundedWithoutOverflow) {
  const auto repeat = [](const std::string& count) {
    return withBody(R"(, "repeat": {"count": )" + count + R"(, "spacing": [1, 1, 1]})");
  };
  // 1e5^3 overflows a 32-bit int, 65536^2 wraps one to 0; factors are checked one by one.
  expectRefused(repeat("[100000, 100000, 100000]"), "bodies[0].repeat.count", "more than 100000 bodies");
  expectRefused(repeat("[65536, 65536, 1]"), "bodies[0].repeat.count", "more than 100000 bodies");
  expectRefused(repeat("[317, 317, 1]"), "bodies[0].repeat.count", "more than 100000 bodies");
  expectRefused(repeat("[18446744073709551615, 1, 1]"), "count[0]", "must be an integer from 1 to 100000");
  expectRefused(repeat("[-1, 1, 1]"), "count[0]", "must be an integer");
  expectRefused(withBody(R"(, "position": [0, 0, 0], "repeat": {"count": [3, 1, 1], "spacing": [1e9, 0, 0]})"),
                "bodies[0].repeat.spacing", "farther than");
}

TEST(SceneHostileInput, NumbersOutsideTheDocumentedRangesNameTheirKey) {
  expectRefused(R"({"dt": 1e200, "bodies": []})", "dt", "must be between 1e-06 and 1");
  expectRefused(R"({"dt": 1e-300, "bodies": []})", "dt", "must be between");
  expectRefused(R"({"steps": 100000000000, "bodies": []})", "steps", "must be an integer from 1 to 1000000");
  expectRefused(withBody(R"(, "mass": 1e-150)"), "bodies[0].mass", "must be at least 1e-09");
  expectRefused(withBody(R"(, "position": [0, 1e300, 0])"), "bodies[0].position[1]", "at most 1e+09");
  expectRefused(withBody(R"(, "velocity": [0, 0, -1e12])"), "bodies[0].velocity[2]", "at most 1e+09");
  expectRefused(R"({"gravity": [0, -1e100, 0], "bodies": []})", "gravity[1]", "at most 1e+09");
  expectRefused(R"({"bodies": [{"shape": {"box": {"half_extents": [1, 1e-20, 1]}}}]})",
                "bodies[0].shape.box.half_extents[1]", "must be at least 1e-09");
  expectRefused(R"({"solver": {"substeps": 1000, "iterations": 1000}, "bodies": []})", "solver",
                "contact sweeps per step");
  // A tiny but non-zero quaternion is a rotation, scaled before normalising.
  EXPECT_EQ(errorOf(withBody(R"(, "orientation": [1e-200, 0, 0, 0])")), "");
}

TEST(SceneHostileInput, BytesThatAreNotJsonTextAreRefused) {
  expectRefused(std::string(R"({"bodies": []})") + '\0' + "trailing", "line 1", "NUL byte");
  expectRefused("{\"bodies\": [],\n\"name\": \"a\xff\xfe\"}", "malformed JSON", "");
}

TEST(SceneHostileInput, OversizedFilesAreRefusedBeforeReading) {
  // Named after the process: two checkouts testing at once must not share it.
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("physdbg_oversized_scene_" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream file(path, std::ios::binary);
    file.seekp(static_cast<std::streamoff>(scene_limits::maxFileBytes));  // sparse: no disk used
    file.put(' ');
  }
  try {
    loadSceneFile(path.string());
    ADD_FAILURE() << "accepted an oversized file";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("at most 67108864"), std::string::npos) << error.what();
  }
  std::filesystem::remove(path);
}

TEST(SceneHostileInput, EngineRejectionsNameTheFileAndTheEntry) {
  SceneDescription scene = parseScene(withBody(""), "entries.json");
  BodyDefinition bad = scene.bodies[0];
  bad.mass = -1;  // past the loader, as a program building scenes might do
  scene.bodies.push_back(bad);
  scene.bodyEntries.push_back(3);
  try {
    buildWorld(scene);
    ADD_FAILURE() << "accepted a negative mass";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("entries.json: bodies[3] (body 1): mass"), std::string::npos)
        << error.what();
  }
  const SceneDescription builtin = resolveScene("stack");
  EXPECT_EQ(builtin.source, "built-in scene stack");
}

// Every prefix and many random corruptions of a valid scene: the loader either
// accepts the text or throws SceneError; nothing else escapes.
TEST(SceneHostileInput, TruncatedAndCorruptedScenesOnlyEverThrowSceneError) {
  const std::string valid = R"({"name": "t", "dt": 0.01, "steps": 10, "gravity": [0, -9.81, 0],
    "solver": {"kind": "sequential_impulse", "substeps": 4, "iterations": 2},
    "camera": {"eye": [5, 5, 5], "target": [0, 0, 0]}, "layers": "shapes,aabbs",
    "bodies": [{"shape": {"box": {"half_extents": [2, 0.5, 2]}}, "static": true},
               {"shape": {"convex": {"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1],[0.2,0.2,0.2]]}},
                "position": [0, 2, 0], "orientation": [1, 0.1, 0, 0], "mass": 2,
                "repeat": {"count": [2, 2, 1], "spacing": [1.5, 1.5, 0]}},
               {"shape": {"capsule": {"radius": 0.3, "half_height": 0.4}}, "position": [0, 5, 0]}]})";
  const auto survives = [](const std::string& text) {
    try {
      buildWorld(parseScene(text, "mutant.json"));
    } catch (const SceneError&) {
    }
  };
  for (std::size_t length = 0; length < valid.size(); ++length) survives(valid.substr(0, length));
  std::mt19937 random(1234);
  std::string alphabet = "{}[]\",:0123456789.eE+-truefalsn \\";
  alphabet += {'\0', '\xff'};
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = random() % text.size();
      text[at] = alphabet[random() % alphabet.size()];
    }
    survives(text);
  }
}

}  // namespace
}  // namespace physdbg
