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
    upload(vertices);
    drawUploaded(mode);
  }

  // The same in two halves, for drawing one upload several times (outlines).
  template <typename Vertex>
  void upload(const std::vector<Vertex>& vertices) {
    uploadBytes(vertices.data(), vertices.size() * sizeof(Vertex), static_cast<GLsizei>(vertices.size()));
  }
  void drawUploaded(GLenum mode);

 private:
  void uploadBytes(const void* data, std::size_t bytes, GLsizei count);
  GlVertexArray vertexArray_;
  GlBuffer buffer_;
  GLsizei count_ = 0;
};

}  // namespace physdbg::render
