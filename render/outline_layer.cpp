#include "render/outline_layer.h"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "render/render_target.h"

namespace physdbg::render {
namespace {

// Rectangles' corners in window pixels (y up); a whole pixel's corner lands
// between pixel centres, so each pixel is in exactly one rectangle.
const char* const kCompositeVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec2 aPixel;\n"
    "uniform vec2 uViewportSize;\n"
    "void main() { gl_Position = vec4(2.0 * aPixel / uViewportSize - 1.0, 0.0, 1.0); }\n";

struct Corner {
  float pixel[2];
};

std::vector<Corner> trianglesOf(const std::vector<PixelRect>& rects) {
  std::vector<Corner> corners;
  corners.reserve(rects.size() * 6);
  for (const PixelRect& rect : rects) {
    const auto x0 = static_cast<float>(rect.x0), y0 = static_cast<float>(rect.y0);
    const auto x1 = static_cast<float>(rect.x1), y1 = static_cast<float>(rect.y1);
    for (const Corner& corner :
         {Corner{{x0, y0}}, Corner{{x1, y0}}, Corner{{x1, y1}}, Corner{{x0, y0}}, Corner{{x1, y1}}, Corner{{x0, y1}}})
      corners.push_back(corner);
  }
  return corners;
}

// The outline colour is the bytes the shifted copies of arrow shafts left
// (shaders.cpp's dark outline colour after llvmpipe's blending): dark, not
// black, so it still reads on a black background. The copies of arrow heads
// were lit, 3 to 10 levels; the outline is now one colour. Outside the layer
// counts as uncovered. An opaque marker's pixel is its texel, byte for byte;
// a translucent marker lies over its neighbours' outline as it lay over their
// dark copies.
const char* const kCompositeFragment =
    "#version 330 core\n"
    "uniform sampler2D uLayer;\n"
    "out vec4 fragColor;\n"
    "float coverage(ivec2 pixel) {\n"
    "  ivec2 size = textureSize(uLayer, 0);\n"
    "  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) return 0.0;\n"
    "  return texelFetch(uLayer, pixel, 0).a;\n"
    "}\n"
    "void main() {\n"
    "  ivec2 pixel = ivec2(gl_FragCoord.xy);\n"
    "  vec4 marker = texelFetch(uLayer, pixel, 0);\n"
    "  if (marker.a == 1.0) {\n"
    "    fragColor = marker;\n"
    "    return;\n"
    "  }\n"
    "  float beside = max(max(coverage(pixel + ivec2(1, 0)), coverage(pixel - ivec2(1, 0))),\n"
    "                     max(coverage(pixel + ivec2(0, 1)), coverage(pixel - ivec2(0, 1))));\n"
    "  if (marker.a == 0.0 && beside == 0.0) discard;\n"
    "  vec4 outline = vec4(vec3(10.0, 10.0, 12.0) / 255.0 * beside, beside);\n"
    "  fragColor = marker + (1.0 - marker.a) * outline;\n"
    "}\n";

}  // namespace

OutlineLayer::OutlineLayer(int width, int height)
    : width_(width),
      height_(height),
      color_(createTexture()),
      framebuffer_(createFramebuffer()),
      composite_(createProgram(kCompositeVertex, kCompositeFragment, "outline composite")),
      corners_(sizeof(Corner), {{0, 2, offsetof(Corner, pixel)}}) {
  glBindTexture(GL_TEXTURE_2D, color_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.get(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("outline layer incomplete (status " + std::to_string(status) + ")");
  glUseProgram(composite_.get());
  glUniform1i(glGetUniformLocation(composite_.get(), "uLayer"), 0);
  glUniform2f(glGetUniformLocation(composite_.get(), "uViewportSize"), static_cast<float>(width),
              static_cast<float>(height));
  checkGlError("creating the outline layer");
}

void OutlineLayer::begin() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, width_, height_);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
}

void OutlineLayer::compositeOnto(const RenderTarget& target, const std::vector<PixelRect>& where) {
  target.bindForDrawing();
  glUseProgram(composite_.get());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, color_.get());
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  corners_.draw(trianglesOf(where), GL_TRIANGLES);
}

}  // namespace physdbg::render
