#pragma once
// A one-pixel dark outline round markers (arrows) without drawing them five
// times. On llvmpipe a marker's cost is its geometry: every copy is shaded,
// set up and binned again, and four shifted dark copies made arrows cost five
// times their own draw. Here the markers are drawn once into a transparent
// single-sample layer, which is then laid over the frame: a pixel the markers
// cover shows them, a pixel beside one (left, right, above or below) shows the
// outline colour. That is exactly what the union of the four one-pixel shifted
// copies covered, so opaque markers' pixels are unchanged and the outline
// covers the same pixels, in one colour (the copies of lit heads were 3-10
// levels darker), but at the image's border, where a marker just outside the
// view no longer leaves its outline on the edge row.
#include <vector>

#include "render/gl_objects.h"
#include "render/marker_footprint.h"
#include "render/vertex_stream.h"

namespace physdbg::render {

class RenderTarget;

class OutlineLayer {
 public:
  // Throws std::runtime_error if GL cannot make the layer's framebuffer.
  OutlineLayer(int width, int height);

  // Binds the layer and clears it to transparent black. Drawing into it with
  // the renderer's blending leaves premultiplied colour.
  void begin() const;

  // Binds `target` and lays the layer, outlined, over the pixels of `where`
  // (which must hold every marker pixel and its neighbours, and must not
  // overlap) with premultiplied blending; the caller restores its own blend
  // function after.
  void compositeOnto(const RenderTarget& target, const std::vector<PixelRect>& where);

 private:
  int width_, height_;
  GlTexture color_;
  GlFramebuffer framebuffer_;
  GlProgram composite_;
  VertexStream corners_;  // two triangles per rectangle, in pixels
};

}  // namespace physdbg::render
