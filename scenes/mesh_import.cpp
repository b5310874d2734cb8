#include "scenes/mesh_import.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <filesystem>
#include <map>
#include <tuple>

namespace physdbg {
namespace {

struct PlacedNode {
  const aiNode* node;
  aiMatrix4x4 transform;  // to the file's root
  bool selected;
};

bool named(const std::vector<std::string>& names, const aiNode& node) {
  return std::find(names.begin(), names.end(), std::string(node.mName.C_Str())) != names.end();
}

// The file's nodes with their transforms, each marked selected when it or a
// parent is named (or nothing is). An explicit stack: a hostile file's
// nesting cannot run the call stack out.
std::vector<PlacedNode> placeNodes(const aiScene& scene, const std::vector<std::string>& names) {
  std::vector<PlacedNode> placed, stack;
  stack.push_back({scene.mRootNode, scene.mRootNode->mTransformation,
                   names.empty() || named(names, *scene.mRootNode)});
  while (!stack.empty()) {
    const PlacedNode current = stack.back();
    stack.pop_back();
    placed.push_back(current);
    for (unsigned c = current.node->mNumChildren; c-- > 0;) {
      const aiNode* child = current.node->mChildren[c];
      stack.push_back({child, current.transform * child->mTransformation, current.selected || named(names, *child)});
    }
  }
  return placed;
}

}  // namespace

ImportedMesh importMesh(const std::string& path, const MeshImportOptions& options) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) throw MeshImportError("cannot read the file: " + error.message());
  if (bytes > options.maxFileBytes)
    throw MeshImportError("the file has " + std::to_string(bytes) + " bytes (at most " +
                          std::to_string(options.maxFileBytes) + ")");
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw MeshImportError(std::string("Assimp cannot read it: ") + importer.GetErrorString());
  const std::vector<PlacedNode> nodes = placeNodes(*scene, options.nodes);
  for (const std::string& name : options.nodes)
    if (std::none_of(nodes.begin(), nodes.end(), [&](const PlacedNode& n) { return name == n.node->mName.C_Str(); }))
      throw MeshImportError("it has no node named '" + name + "'");
  // Count before copying anything.
  std::size_t faces = 0;
  for (const PlacedNode& placed : nodes) {
    if (!placed.selected) continue;
    for (unsigned m = 0; m < placed.node->mNumMeshes; ++m) {
      faces += scene->mMeshes[placed.node->mMeshes[m]]->mNumFaces;
      if (faces > options.maxTriangles)
        throw MeshImportError("it has more than " + std::to_string(options.maxTriangles) + " triangles");
    }
  }
  ImportedMesh mesh;
  mesh.triangles.reserve(faces);
  std::map<std::tuple<double, double, double>, std::uint32_t> welded;
  std::vector<std::uint32_t> index;
  for (const PlacedNode& placed : nodes) {
    if (!placed.selected) continue;
    for (unsigned m = 0; m < placed.node->mNumMeshes; ++m) {
      const aiMesh& part = *scene->mMeshes[placed.node->mMeshes[m]];
      index.assign(part.mNumVertices, 0);
      for (unsigned v = 0; v < part.mNumVertices; ++v) {
        const aiVector3D p = placed.transform * part.mVertices[v];
        Vec3 point(p.x, p.y, p.z);
        if (!point.allFinite()) throw MeshImportError("a vertex of mesh '" + std::string(part.mName.C_Str()) +
                                                      "' is not finite");
        if (options.zUp) point = Vec3(point.x(), point.z(), -point.y());
        point = point.cwiseProduct(options.scale);
        const auto [at, inserted] =
            welded.try_emplace({point.x(), point.y(), point.z()}, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (inserted) mesh.vertices.push_back(point);
        else ++mesh.weldedVertices;
        index[v] = at->second;
      }
      for (unsigned f = 0; f < part.mNumFaces; ++f) {
        const aiFace& face = part.mFaces[f];
        if (face.mNumIndices != 3) {
          ++mesh.skippedPrimitives;
          continue;
        }
        mesh.triangles.push_back({index[face.mIndices[0]], index[face.mIndices[1]], index[face.mIndices[2]]});
      }
    }
  }
  if (mesh.triangles.empty())
    throw MeshImportError(options.nodes.empty() ? "it holds no triangles" : "the named nodes hold no triangles");
  return mesh;
}

}  // namespace physdbg
