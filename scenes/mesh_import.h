#pragma once
// Triangle meshes from the files other tools write: OBJ, glTF 2.0 (.gltf and
// .glb), STL, PLY and the other formats Assimp (Debian's libassimp-dev)
// reads. A maintained reader of a dozen formats beats a hand-written one of
// each; only the walk over Assimp's node tree and the checks are ours.
//
// Every selected node's meshes are placed by the node's transform (and its
// parents'), triangulated, and welded: vertices at bit-identical positions
// become one, whatever normals or texture coordinates the file gave each
// copy, so the mesh's edges are shared and its active edges found
// (triangle_mesh_collider.h). Points and lines are skipped and counted.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/colliders/triangle_mesh_collider.h"

namespace physdbg {

class MeshImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MeshImportOptions {
  Vec3 scale = Vec3::Ones();       // applied last, in the scene's frame
  bool zUp = false;                // the file's up is +z (Blender's, most STL): turned so that it is +y
  std::vector<std::string> nodes;  // only these nodes and what hangs below them; empty: the whole file
  std::size_t maxTriangles = 10'000'000;
  std::uintmax_t maxFileBytes = std::uintmax_t{1} << 30;
};

struct ImportedMesh {
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  std::size_t skippedPrimitives = 0;  // points and lines in the file
  std::size_t weldedVertices = 0;     // copies merged into another at the same position
};

// Throws MeshImportError saying what is wrong (the file's size or triangle
// count past the limits, Assimp's reason for not reading it, a named node
// that is not there, no triangles); the message does not repeat the path.
ImportedMesh importMesh(const std::string& path, const MeshImportOptions& options);

}  // namespace physdbg
