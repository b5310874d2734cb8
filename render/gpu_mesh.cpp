#include "render/gpu_mesh.h"

#include <cstddef>

namespace physdbg::render {
namespace {

void floatAttribute(GLuint location, GLint size, GLsizei stride, std::size_t offset, GLuint divisor) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(location, divisor);
}

}  // namespace

InstancedMesh uploadInstancedMesh(const UnitMesh& mesh, GLenum mode) {
  InstancedMesh gpu{createVertexArray(), createBuffer(), createBuffer(), createBuffer(),
                    static_cast<GLsizei>(mesh.indices.size()), mode};
  glBindVertexArray(gpu.vertexArray.get());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  floatAttribute(0, 4, sizeof(MeshVertex), offsetof(MeshVertex, position), 0);
  floatAttribute(1, 3, sizeof(MeshVertex), offsetof(MeshVertex, normal), 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, gpu.instances.get());
  floatAttribute(2, 3, sizeof(Instance), offsetof(Instance, translation), 1);
  floatAttribute(3, 4, sizeof(Instance), offsetof(Instance, rotation), 1);
  floatAttribute(4, 4, sizeof(Instance), offsetof(Instance, scale), 1);
  floatAttribute(5, 4, sizeof(Instance), offsetof(Instance, color), 1);
  glBindVertexArray(0);
  checkGlError("uploading a mesh");
  return gpu;
}

void drawInstances(InstancedMesh& mesh, const std::vector<Instance>& instances) {
  uploadInstances(mesh, instances);
  drawUploadedInstances(mesh);
}

void uploadInstances(InstancedMesh& mesh, const std::vector<Instance>& instances) {
  mesh.instanceCount = static_cast<GLsizei>(instances.size());
  if (instances.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, mesh.instances.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(Instance)), instances.data(),
               GL_STREAM_DRAW);
}

void drawUploadedInstances(const InstancedMesh& mesh) {
  if (mesh.instanceCount == 0 || mesh.indexCount == 0) return;
  glBindVertexArray(mesh.vertexArray.get());
  glDrawElementsInstanced(mesh.mode, mesh.indexCount, GL_UNSIGNED_INT, nullptr, mesh.instanceCount);
  glBindVertexArray(0);
}

}  // namespace physdbg::render
