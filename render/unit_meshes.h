#pragma once
// Unit geometry shared by all instances of a primitive kind, built on the CPU.
// Vertex w is the capsule stretch sign: the shader moves a vertex by
// w * halfHeight along local y, so one sphere mesh with a doubled equator
// draws both spheres (halfHeight 0) and capsules.
#include <cstdint>
#include <vector>

#include "debugdraw/primitives.h"

namespace physdbg::render {

struct MeshVertex {
  float position[4];  // xyz, w = stretch sign (-1, 0, +1)
  float normal[3];
};

struct UnitMesh {
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;
};

UnitMesh unitCube();                            // [-1,1]^3, flat face normals
UnitMesh unitCubeEdges();                       // 12 edges of [-1,1]^3 as line pairs
UnitMesh capsuleSphere(int segments, int rings);  // unit sphere split at the equator
// Base radius 1 at y=0, apex at y=1, flat shaded with shared vertices: each
// face's normal is on its first vertex, for a `flat` normal drawn with
// GL_FIRST_VERTEX_CONVENTION (shaders::kFlatSolidVertex). Arrow heads are
// drawn five times a frame (four outline copies), and llvmpipe shades every
// vertex on the drawing thread: 2n+4 vertices instead of 6n, the same triangles.
UnitMesh unitCone(int segments);

// Flat-shaded copy of a triangle mesh (one normal per face). Throws
// std::invalid_argument for an index count not a multiple of 3 or an index
// out of range.
UnitMesh flatShadedMesh(const debugdraw::TriangleMesh& mesh);

}  // namespace physdbg::render
