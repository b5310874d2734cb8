#include "render/vertex_stream.h"

namespace physdbg::render {

VertexStream::VertexStream(GLsizei stride, std::initializer_list<FloatAttribute> attributes)
    : vertexArray_(createVertexArray()), buffer_(createBuffer()) {
  glBindVertexArray(vertexArray_.get());
  glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
  for (const FloatAttribute& attribute : attributes) {
    glEnableVertexAttribArray(attribute.location);
    glVertexAttribPointer(attribute.location, attribute.size, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(attribute.offset));
  }
  glBindVertexArray(0);
}

void VertexStream::uploadBytes(const void* data, std::size_t bytes, GLsizei count) {
  count_ = count;
  if (count == 0) return;
  glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STREAM_DRAW);
}

void VertexStream::drawUploaded(GLenum mode) {
  if (count_ == 0) return;
  glBindVertexArray(vertexArray_.get());
  glDrawArrays(mode, 0, count_);
  glBindVertexArray(0);
}

}  // namespace physdbg::render
