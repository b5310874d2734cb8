#include "render/render_target.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physdbg::render {
namespace {

GlRenderbuffer storage(GLenum format, int width, int height, int samples) {
  GlRenderbuffer buffer = createRenderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, buffer.get());
  if (samples > 0)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  return buffer;
}

GlFramebuffer framebuffer(const GlRenderbuffer& color, const GlRenderbuffer& depth) {
  GlFramebuffer target = createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.get());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("render target incomplete (status " + std::to_string(status) + ")");
  return target;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {
  color_ = storage(GL_RGBA8, width, height, 0);
  depth_ = storage(GL_DEPTH_COMPONENT24, width, height, 0);
  resolved_ = framebuffer(color_, depth_);
  if (samples > 0) {
    multisampleColor_ = storage(GL_RGBA8, width, height, samples);
    multisampleDepth_ = storage(GL_DEPTH_COMPONENT24, width, height, samples);
    multisampled_ = framebuffer(multisampleColor_, multisampleDepth_);
  }
  checkGlError("creating the render target");
}

void RenderTarget::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? multisampled_.get() : resolved_.get());
  glViewport(0, 0, width_, height_);
}

Image RenderTarget::read() const {
  if (samples_ > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.get());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.get());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t rowBytes = static_cast<std::size_t>(width_) * 4;
  // Read straight into the image and flip in place: one 3.7 MB buffer at
  // 1280x720 instead of two, which halves the page faults and copies.
  Image image{width_, height_, std::vector<std::uint8_t>(rowBytes * height_)};
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  checkGlError("reading pixels");
  for (int row = 0; row < height_ / 2; ++row)  // GL's first row is the bottom one
    std::swap_ranges(image.rgba.begin() + row * rowBytes, image.rgba.begin() + (row + 1) * rowBytes,
                     image.rgba.begin() + (height_ - 1 - row) * rowBytes);
  return image;
}

}  // namespace physdbg::render
