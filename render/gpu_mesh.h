#pragma once
// A unit mesh on the GPU with its per-instance buffer, drawn with one
// instanced call. Vertex attributes 0-1 come from the mesh, 2-5 per instance.
#include <vector>

#include "render/frame_batches.h"
#include "render/gl_objects.h"
#include "render/unit_meshes.h"

namespace physdbg::render {

struct InstancedMesh {
  GlVertexArray vertexArray;
  GlBuffer vertices, indices, instances;
  GLsizei indexCount = 0;
  GLenum mode = GL_TRIANGLES;
  GLsizei instanceCount = 0;  // uploaded last
};

InstancedMesh uploadInstancedMesh(const UnitMesh& mesh, GLenum mode);
// Uploads the instances and draws them all; nothing for an empty list.
void drawInstances(InstancedMesh& mesh, const std::vector<Instance>& instances);
// The same in two halves, for drawing one upload several times (outlines).
void uploadInstances(InstancedMesh& mesh, const std::vector<Instance>& instances);
void drawUploadedInstances(const InstancedMesh& mesh);

}  // namespace physdbg::render
