#include "render/marker_footprint.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace physdbg::render {
namespace {

using Eigen::Vector3d;

// Tiles an arrow may reach, one flag per tile, row by row from the bottom.
class TileMask {
 public:
  TileMask(int width, int height)
      : width_(width),
        height_(height),
        columns_((width + kFootprintTilePixels - 1) / kFootprintTilePixels),
        rows_((height + kFootprintTilePixels - 1) / kFootprintTilePixels),
        marked_(static_cast<std::size_t>(columns_) * rows_, 0) {}

  // Marks the tiles under the window-space box [x0, x1] x [y0, y1].
  void mark(double x0, double y0, double x1, double y1) {
    if (!(x1 >= 0 && y1 >= 0 && x0 < width_ && y0 < height_)) return;  // off screen (or NaN)
    const int column0 = tileOf(x0, columns_), column1 = tileOf(x1, columns_);
    const int row0 = tileOf(y0, rows_), row1 = tileOf(y1, rows_);
    for (int row = row0; row <= row1; ++row)
      std::fill(marked_.begin() + row * columns_ + column0, marked_.begin() + row * columns_ + column1 + 1, 1);
  }

  std::vector<PixelRect> runs() const {
    std::vector<PixelRect> rects;
    for (int row = 0; row < rows_; ++row) {
      for (int column = 0; column < columns_;) {
        if (!marked_[row * columns_ + column]) {
          ++column;
          continue;
        }
        const int first = column;
        while (column < columns_ && marked_[row * columns_ + column]) ++column;
        rects.push_back({first * kFootprintTilePixels, row * kFootprintTilePixels,
                         std::min(column * kFootprintTilePixels, width_),
                         std::min((row + 1) * kFootprintTilePixels, height_)});
      }
    }
    return rects;
  }

 private:
  // Clamped before the conversion: a point just in front of the eye plane
  // projects past any int.
  static int tileOf(double pixel, int tiles) {
    return static_cast<int>(std::clamp(std::floor(pixel / kFootprintTilePixels), 0.0, tiles - 1.0));
  }

  int width_, height_, columns_, rows_;
  std::vector<unsigned char> marked_;
};

// Window-space bounds of points; unbounded once one lies at or behind the eye.
class ProjectedBounds {
 public:
  ProjectedBounds(const Eigen::Matrix4d& viewProjection, int width, int height)
      : viewProjection_(viewProjection), width_(width), height_(height) {}

  void add(const Vector3d& point) {
    const Eigen::Vector4d clip = viewProjection_ * point.homogeneous();
    if (!(clip.w() > 0)) {
      behindEye_ = true;
      return;
    }
    const double x = (clip.x() / clip.w() + 1) * 0.5 * width_, y = (clip.y() / clip.w() + 1) * 0.5 * height_;
    min_ = min_.cwiseMin(Eigen::Vector2d(x, y));
    max_ = max_.cwiseMax(Eigen::Vector2d(x, y));
  }

  bool behindEye() const { return behindEye_; }
  const Eigen::Vector2d& min() const { return min_; }
  const Eigen::Vector2d& max() const { return max_; }

 private:
  Eigen::Matrix4d viewProjection_;
  int width_, height_;
  bool behindEye_ = false;
  Eigen::Vector2d min_ = Eigen::Vector2d::Constant(INFINITY), max_ = Eigen::Vector2d::Constant(-INFINITY);
};

Vector3d positionOf(const float* position) { return Vector3d(position[0], position[1], position[2]); }

// The apex and the corners of the square round the base, as the solid
// vertex shader places the unit cone (base radius 1 at y = 0, apex at y = 1).
void addHead(const Instance& head, ProjectedBounds& bounds) {
  const Eigen::Quaterniond rotation(head.rotation[3], head.rotation[0], head.rotation[1], head.rotation[2]);
  const Vector3d base = positionOf(head.translation);
  const double radius = head.scale[0], length = head.scale[1], depth = head.scale[2];
  bounds.add(base + rotation * Vector3d(0, length, 0));
  for (double x : {-radius, radius})
    for (double z : {-depth, depth}) bounds.add(base + rotation * Vector3d(x, 0, z));
}

}  // namespace

std::vector<PixelRect> arrowFootprint(const FrameBatches& batches, const Eigen::Matrix4f& viewProjection, int width,
                                      int height, double marginPixels) {
  TileMask mask(width, height);
  const Eigen::Matrix4d transform = viewProjection.cast<double>();
  for (std::size_t arrow = 0; arrow < batches.arrowHeads.size(); ++arrow) {
    ProjectedBounds bounds(transform, width, height);
    bounds.add(positionOf(batches.arrowShafts[2 * arrow].position));
    bounds.add(positionOf(batches.arrowShafts[2 * arrow + 1].position));
    addHead(batches.arrowHeads[arrow], bounds);
    if (bounds.behindEye() || !bounds.min().allFinite() || !bounds.max().allFinite()) return {{0, 0, width, height}};
    mask.mark(bounds.min().x() - marginPixels, bounds.min().y() - marginPixels, bounds.max().x() + marginPixels,
              bounds.max().y() + marginPixels);
  }
  return mask.runs();
}

}  // namespace physdbg::render
