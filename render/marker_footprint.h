#pragma once
// The part of the image the arrows of a frame can touch, outline included, as
// a few rectangles. Laying the outline layer over the frame runs a fragment
// per pixel it covers, and on llvmpipe a full 1280x720 pass costs about as
// much as drawing three thousand arrows; the arrows of a debug picture cover
// a fraction of it.
#include <Eigen/Core>
#include <vector>

#include "render/frame_batches.h"

namespace physdbg::render {

// Pixels [x0, x1) x [y0, y1) in GL window coordinates (y up).
struct PixelRect {
  int x0, y0, x1, y1;
};

inline constexpr int kFootprintTilePixels = 16;

// Tiles of kFootprintTilePixels that an arrow's shaft or head, grown by
// `marginPixels`, may reach, merged into runs along each row of tiles: no two
// rectangles overlap, and together they hold every pixel the arrows can
// rasterise to and its neighbours. The bounds are the projections of each
// shaft's ends and of each head's apex and the corners of the square round
// its base (the cone lies in their convex hull). With any of those points at
// or behind the eye (w <= 0, drawn through depth clamping), or projected so
// close to the eye plane that its pixel is not finite, it answers the whole
// image.
std::vector<PixelRect> arrowFootprint(const FrameBatches& batches, const Eigen::Matrix4f& viewProjection, int width,
                                      int height, double marginPixels);

}  // namespace physdbg::render
