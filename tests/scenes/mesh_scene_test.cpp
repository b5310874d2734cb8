// The "mesh" shape in scene files: read into a TriangleMeshCollider, bad
// meshes refused with the key that is wrong, degenerate triangles dropped
// with a note.
#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace physdbg
