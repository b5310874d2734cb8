#pragma once
// A vertex buffer refilled every frame (lines, points, text): one draw call
// for everything of its kind.
#include <initializer_list>
#include <vector>

#include "render/gl_objects.h"

namespace physdbg::render {

struct FloatAttribute {
  GLuint location;
  GLint size;
  std::size_t offset;
};

class VertexStream {
 public:
  VertexStream(GLsizei stride, std::initializer_list<FloatAttribute> attributes);

  template <typename Vertex>
  void draw(const std::vector<Vertex>& vertices, GLenum mode) {
    drawBytes(vertices.data(), vertices.size() * sizeof(Vertex), static_cast<GLsizei>(vertices.size()), mode);
  }

 private:
  void drawBytes(const void* data, std::size_t bytes, GLsizei count, GLenum mode);
  GlVertexArray vertexArray_;
  GlBuffer buffer_;
};

}  // namespace physdbg::render
