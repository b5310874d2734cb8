// Meshes read from files through Assimp: the same level as OBJ and glTF
// gives the same triangles; scale, up axis and node selection; files that
// cannot be read, or are too big, are errors naming the file and the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/colliders/triangle_mesh_collider.h"
#include "scenes/mesh_import.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

const std::string levels = std::string(PHYSDBG_SOURCE_DIR) + "/scenes/levels/";

// Each triangle as its three corner positions, rotated so the smallest
// corner comes first (keeping the winding), the list sorted: the geometry,
// whatever order and numbering of vertices a format gives.
std::vector<std::array<double, 9>> corners(const std::vector<Vec3>& vertices, const std::vector<MeshTriangle>& triangles) {
  std::vector<std::array<double, 9>> out;
  for (const MeshTriangle& triangle : triangles) {
    std::array<Vec3, 3> p = {vertices[triangle[0]], vertices[triangle[1]], vertices[triangle[2]]};
    const auto less = [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    };
    const int first = static_cast<int>(std::min_element(p.begin(), p.end(), less) - p.begin());
    std::rotate(p.begin(), p.begin() + first, p.end());
    out.push_back({p[0].x(), p[0].y(), p[0].z(), p[1].x(), p[1].y(), p[1].z(), p[2].x(), p[2].y(), p[2].z()});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(MeshImport, ObjAndGltfOfOneLevelGiveTheSameTriangles) {
  const ImportedMesh obj = importMesh(levels + "valley.obj", {});
  const ImportedMesh gltf = importMesh(levels + "valley.gltf", {});
  EXPECT_EQ(obj.triangles.size(), 128u);
  EXPECT_EQ(obj.vertices.size(), 81u);  // welded: OBJ corners arrive one per face corner
  EXPECT_EQ(gltf.vertices.size(), 81u);
  EXPECT_EQ(corners(obj.vertices, obj.triangles), corners(gltf.vertices, gltf.triangles));
  // Welded, the inner edges are shared: only the border and the real folds are active.
  const TriangleMeshCollider mesh(obj.vertices, obj.triangles);
  EXPECT_LT(mesh.activeEdgeCount(), 3 * mesh.triangles().size() / 2);
}

TEST(MeshImport, ScaleAndUpAxisApply) {
  MeshImportOptions options;
  options.zUp = true;
  options.scale = Vec3(2, 3, 4);
  const ImportedMesh plain = importMesh(levels + "valley.obj", {});
  const ImportedMesh turned = importMesh(levels + "valley.obj", options);
  ASSERT_EQ(plain.vertices.size(), turned.vertices.size());
  for (std::size_t i = 0; i < plain.vertices.size(); ++i) {
    const Vec3& p = plain.vertices[i];
    EXPECT_EQ(turned.vertices[i], Vec3(2 * p.x(), 3 * p.z(), -4 * p.y()));
  }
}

TEST(MeshImport, NodesSelectAndMissingOnesAreNamed) {
  MeshImportOptions options;
  options.nodes = {"valley"};
  EXPECT_EQ(importMesh(levels + "valley.gltf", options).triangles.size(), 128u);
  options.nodes = {"valley", "ridge"};
  try {
    importMesh(levels + "valley.gltf", options);
    FAIL() << "no error";
  } catch (const MeshImportError& error) {
    EXPECT_NE(std::string(error.what()).find("'ridge'"), std::string::npos) << error.what();
  }
}

TEST(MeshImport, LimitsAreCheckedBeforeBuilding) {
  MeshImportOptions options;
  options.maxFileBytes = 1000;
  EXPECT_THROW(importMesh(levels + "valley.obj", options), MeshImportError);
  options = {};
  options.maxTriangles = 100;
  try {
    importMesh(levels + "valley.obj", options);
    FAIL() << "no error";
  } catch (const MeshImportError& error) {
    EXPECT_NE(std::string(error.what()).find("more than 100 triangles"), std::string::npos) << error.what();
  }
}

TEST(MeshImport, SceneFilesNameTheMeshFileAndAssimpsReason) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "physdbg_mesh_import_test";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "broken.obj") << "this is not a mesh\n";
  std::ofstream(folder / "level.json") << R"({"bodies": [{"shape": {"mesh": {"file": "broken.obj"}}, "static": true}]})";
  std::ofstream(folder / "missing.json")
      << R"({"bodies": [{"shape": {"mesh": {"file": "nowhere.obj"}}, "static": true}]})";
  for (const char* scene : {"level.json", "missing.json"}) {
    try {
      loadSceneFile((folder / scene).string());
      ADD_FAILURE() << scene << ": no error";
    } catch (const SceneError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("bodies[0].shape.mesh.file"), std::string::npos) << message;
      EXPECT_NE(message.find(scene == std::string("level.json") ? "broken.obj" : "nowhere.obj"), std::string::npos)
          << message;
    }
  }
  std::filesystem::remove_all(folder);
}

TEST(MeshImport, ShippedLevelScenesLoadFromTheirFolderAndRunAlike) {
  const SceneDescription obj = loadSceneFile(std::string(PHYSDBG_SOURCE_DIR) + "/scenes/valley_obj.json");
  const SceneDescription gltf = loadSceneFile(std::string(PHYSDBG_SOURCE_DIR) + "/scenes/valley_gltf.json");
  ASSERT_EQ(obj.bodies[0].collider->kind(), ColliderKind::TriangleMesh);
  World a = buildWorld(obj), b = buildWorld(gltf);
  for (int step = 0; step < 60; ++step) {
    a.step();
    b.step();
  }
  for (std::size_t i = 0; i < a.bodies().size(); ++i) EXPECT_EQ(a.bodies()[i].position(), b.bodies()[i].position());
}

TEST(MeshImport, ConvexTrueMakesTheHullForADynamicBody) {
  const SceneDescription scene = parseScene(
      R"({"bodies": [{"shape": {"mesh": {"file": ")" + levels + R"(valley.obj", "convex": true, "scale": 0.1}},
          "mass": 2}]})",
      "rock.json");
  ASSERT_EQ(scene.bodies[0].collider->kind(), ColliderKind::ConvexMesh);
  const Aabb bounds = scene.bodies[0].collider->localBounds();
  EXPECT_NEAR(bounds.max.x() - bounds.min.x(), 1.6, 1e-9);  // the valley's 16 m, scaled
  World world = buildWorld(scene);
  world.step();
  EXPECT_LT(world.body(0).linearVelocity().y(), 0.0);  // dynamic: it falls
}

}  // namespace
}  // namespace physdbg
