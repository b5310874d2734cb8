#include "gpu/storage_buffer.h"

#include <stdexcept>

#include "render/gl_headers.h"

namespace physdbg::gpu {

StorageBuffer::StorageBuffer(std::string label) : label_(std::move(label)), buffer_(render::createBuffer()) {}

void StorageBuffer::reserve(std::size_t bytes) {
  if (bytes <= capacity_) return;
  std::size_t grown = capacity_ == 0 ? 256 : capacity_;
  while (grown < bytes) grown *= 2;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_.get());
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(grown), nullptr, GL_DYNAMIC_DRAW);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("GPU buffer '" + label_ + "': cannot allocate " + std::to_string(grown) + " bytes");
  capacity_ = grown;
}

void StorageBuffer::upload(std::size_t offset, const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  if (offset + bytes > capacity_) throw std::logic_error("GPU buffer '" + label_ + "': upload past its end");
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_.get());
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void StorageBuffer::download(std::size_t offset, void* data, std::size_t bytes) const {
  if (bytes == 0) return;
  if (offset + bytes > capacity_) throw std::logic_error("GPU buffer '" + label_ + "': download past its end");
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_.get());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void StorageBuffer::bind(unsigned binding) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer_.get());
}

}  // namespace physdbg::gpu
