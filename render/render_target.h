#pragma once
// The framebuffer the renderer draws into: colour + depth renderbuffers, with
// an optional multisampled pair resolved by a blit before read-back. Owning
// the framebuffer keeps the renderer independent of the context backend.
#include "render/gl_objects.h"
#include "render/image.h"

namespace physdbg::render {

class RenderTarget {
 public:
  // Throws std::runtime_error if the framebuffer is incomplete.
  RenderTarget(int width, int height, int samples);
  void bindForDrawing() const;
  Image read() const;  // resolves if multisampled; rows top to bottom

 private:
  int width_, height_, samples_;
  GlRenderbuffer color_, depth_, multisampleColor_, multisampleDepth_;
  GlFramebuffer resolved_, multisampled_;
};

}  // namespace physdbg::render
