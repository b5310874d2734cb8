// The "mesh" shape in scene files: read into a TriangleMeshCollider, bad
// meshes refused with the key that is wrong, degenerate triangles dropped
// with a note.
#include <gtest/gtest.h>

#include <string>

#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseScene(text, "level.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

constexpr char quad[] = R"("vertices": [[-1,0,-1],[-1,0,1],[1,0,-1],[1,0,1]], "triangles": [[0,1,2],[2,1,3]])";

TEST(MeshScene, AStaticMeshIsRead) {
  const SceneDescription scene = parseScene(std::string(R"({"bodies": [{"shape": {"mesh": {)") + quad +
                                                R"(}}, "static": true, "position": [0, -1, 0]}]})",
                                            "level.json");
  ASSERT_EQ(scene.bodies.size(), 1u);
  ASSERT_EQ(scene.bodies[0].collider->kind(), ColliderKind::TriangleMesh);
  const auto& mesh = static_cast<const TriangleMeshCollider&>(*scene.bodies[0].collider);
  EXPECT_EQ(mesh.triangles().size(), 2u);
  EXPECT_EQ(mesh.activeEdgeCount(), 4u);  // the border; the diagonal is flat
  EXPECT_TRUE(scene.notes.empty());
  World world = buildWorld(scene);
  EXPECT_EQ(world.bodies().size(), 1u);
}

TEST(MeshScene, BadMeshesNameTheKey) {
  const auto body = [](const std::string& mesh, const std::string& rest = R"(, "static": true)") {
    return R"({"bodies": [{"shape": {"mesh": {)" + mesh + "}}" + rest + "}]}";
  };
  EXPECT_NE(errorOf(body(R"("vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,2,1],[0,1,3]])"))
                .find("bodies[0].shape.mesh.triangles[1][2]"),
            std::string::npos);
  EXPECT_NE(errorOf(body(R"("vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,2,-1]])")).find("triangles[0][2]"),
            std::string::npos);
  EXPECT_NE(errorOf(body(R"("vertices": [[0,0,0],[1,0,0],[0,0,1]], "triangles": [[0,2]])")).find("triangles[0]"),
            std::string::npos);
  EXPECT_NE(errorOf(body(R"("vertices": [[0,0,0],[1,0]], "triangles": [[0,1,1]])")).find("vertices[1]"),
            std::string::npos);
  EXPECT_NE(errorOf(body(R"("vertices": [], "triangles": [])")).find("triangles"), std::string::npos);
  EXPECT_NE(errorOf(body(R"("vertices": [[0,0,0],[1,0,0],[2,0,0]], "triangles": [[0,1,2]])")).find("degenerate"),
            std::string::npos);
  EXPECT_NE(errorOf(body(quad, "")).find("cannot be dynamic"), std::string::npos);  // neither static nor kinematic
  EXPECT_NE(errorOf(body(std::string(quad) + R"(, "active_edge_degrees": 200)")).find("active_edge_degrees"),
            std::string::npos);
  EXPECT_NE(errorOf(body(std::string(quad) + R"(, "file": "x.obj")")).find("both file and vertices"), std::string::npos);
  EXPECT_NE(errorOf(body(std::string(quad) + R"(, "up_axis": "z")")).find("up_axis"), std::string::npos);
  EXPECT_NE(errorOf(body(R"("file": "x.obj", "up_axis": "x")")).find("up_axis"), std::string::npos);
}

TEST(MeshScene, DegenerateTrianglesAreDroppedWithANote) {
  const SceneDescription scene = parseScene(
      R"({"bodies": [{"shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[0,0,1],[2,0,0]],
          "triangles": [[0,2,1],[0,1,3],[1,1,2]]}}, "kinematic": true}]})",
      "level.json");
  ASSERT_EQ(scene.notes.size(), 1u);
  EXPECT_NE(scene.notes[0].find("level.json"), std::string::npos) << scene.notes[0];
  EXPECT_NE(scene.notes[0].find("bodies[0].shape.mesh"), std::string::npos) << scene.notes[0];
  EXPECT_NE(scene.notes[0].find("dropped 2 degenerate triangles"), std::string::npos) << scene.notes[0];
}

TEST(MeshScene, HeightfieldsFromSamplesAndFromA16BitPng) {
  const SceneDescription inline_ = parseScene(
      R"({"bodies": [{"shape": {"heightfield": {"samples": [[0, 1, 2], [1, 2, 3]], "spacing": [0.5, 2], "scale": 3}},
          "static": true}]})",
      "terrain.json");
  ASSERT_EQ(inline_.bodies[0].collider->kind(), ColliderKind::Heightfield);
  const auto& small = static_cast<const HeightfieldCollider&>(*inline_.bodies[0].collider);
  EXPECT_EQ(small.columns(), 3);
  EXPECT_EQ(small.rows(), 2);
  EXPECT_EQ(small.samplePoint(2, 1), Vec3(0.5, 9.0, 1.0));
  const SceneDescription hills = loadSceneFile(std::string(PHYSDBG_SOURCE_DIR) + "/scenes/terrain.json");
  const auto& field = static_cast<const HeightfieldCollider&>(*hills.bodies[0].collider);
  EXPECT_EQ(field.columns(), 65);
  EXPECT_EQ(field.rows(), 65);
  EXPECT_GT(field.localBounds().max.y() - field.localBounds().min.y(), 1.0);
}

TEST(MeshScene, BadHeightfieldsNameTheKey) {
  const auto field = [](const std::string& parameters, const std::string& rest = R"(, "static": true)") {
    return R"({"bodies": [{"shape": {"heightfield": {)" + parameters + "}}" + rest + "}]}";
  };
  EXPECT_NE(errorOf(field(R"("samples": [[0, 1], [1]], "spacing": [1, 1])")).find("heightfield.samples[1]"),
            std::string::npos);
  EXPECT_NE(errorOf(field(R"("samples": [[0, 1]], "spacing": [1, 1])")).find("2 rows"), std::string::npos);
  EXPECT_NE(errorOf(field(R"("samples": [[0, 1], [1, 2]], "spacing": [1, 0])")).find("spacing[1]"),
            std::string::npos);
  EXPECT_NE(errorOf(field(R"("samples": [[0, 1], [1, 2]])")).find("spacing"), std::string::npos);
  EXPECT_NE(errorOf(field(R"("spacing": [1, 1])")).find("samples or file"), std::string::npos);
  EXPECT_NE(errorOf(field(R"("samples": [[0, 1], [1, 2]], "spacing": [1, 1])", "")).find("cannot be dynamic"),
            std::string::npos);
  const std::string eightBit = std::string(PHYSDBG_SOURCE_DIR) + "/tests/golden/mesa-22.3.6-llvmpipe/default_shapes_wire_overlay.png";
  EXPECT_NE(errorOf(field(R"("file": ")" + eightBit + R"(", "spacing": [1, 1])")).find("16-bit grayscale"),
            std::string::npos);
  EXPECT_NE(errorOf(field(R"("file": "nowhere.png", "spacing": [1, 1])")).find("heightfield.file"),
            std::string::npos);
}

TEST(FilterScene, LayersByNameListOrBitsAndSensors) {
  const SceneDescription scene = parseScene(
      R"({"collision_layers": ["ground", "debris", "player"], "bodies": [
          {"shape": {"sphere": {"radius": 1}}, "layer": "debris", "collides_with": ["ground", "player"]},
          {"shape": {"sphere": {"radius": 1}}, "layer": 6, "collides_with": 1, "sensor": true},
          {"shape": {"sphere": {"radius": 1}}}]})",
      "filters.json");
  EXPECT_EQ(scene.bodies[0].filter.layer, 0b010u);
  EXPECT_EQ(scene.bodies[0].filter.collidesWith, 0b101u);
  EXPECT_EQ(scene.bodies[1].filter.layer, 6u);
  EXPECT_EQ(scene.bodies[1].filter.collidesWith, 1u);
  EXPECT_TRUE(scene.bodies[1].isSensor);
  EXPECT_TRUE(scene.bodies[2].filter.isDefault());
  EXPECT_FALSE(scene.bodies[2].isSensor);
}

TEST(FilterScene, BadLayersNameTheKey) {
  EXPECT_NE(errorOf(R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "layer": "debris"}]})").find("bodies[0].layer"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"collision_layers": ["a"], "bodies": [{"shape": {"sphere": {"radius": 1}},
                       "collides_with": ["a", "b"]}]})")
                .find("collides_with[1]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"collision_layers": ["a", "a"], "bodies": []})").find("twice"), std::string::npos);
  EXPECT_NE(errorOf(R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "layer": -1}]})").find("layer"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "sensor": 1}]})").find("sensor"),
            std::string::npos);
}

}  // namespace
}  // namespace physdbg
