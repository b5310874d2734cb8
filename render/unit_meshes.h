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
UnitMesh unitCone(int segments);                // base radius 1 at y=0, apex at y=1

// Flat-shaded copy of a triangle mesh (one normal per face). Throws
// std::invalid_argument for an index count not a multiple of 3 or an index
// out of range.
UnitMesh flatShadedMesh(const debugdraw::TriangleMesh& mesh);

}  // namespace physdbg::render
