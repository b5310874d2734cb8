#pragma once
// A shader storage buffer that persists across steps: it grows (never
// shrinks) to the largest size asked of it, so a steady scene allocates
// once. The compute context must be current for every call.
#include <cstddef>
#include <string>

#include "render/gl_objects.h"

namespace physdbg::gpu {

class StorageBuffer {
 public:
  explicit StorageBuffer(std::string label);

  // Makes room for `bytes`, keeping nothing of the old contents when it grows.
  void reserve(std::size_t bytes);
  std::size_t capacity() const { return capacity_; }
  void upload(std::size_t offset, const void* data, std::size_t bytes);
  // Waits for the shaders that wrote it (a barrier) and copies it back.
  void download(std::size_t offset, void* data, std::size_t bytes) const;
  void bind(unsigned binding) const;
  unsigned name() const { return buffer_.get(); }

 private:
  std::string label_;
  render::GlBuffer buffer_;
  std::size_t capacity_ = 0;
};

}  // namespace physdbg::gpu
