#pragma once
// 2D drawings (tree diagrams, plots) are debug-draw frames in the z = 0
// plane with x = pixel column and y = -pixel row, seen by an orthographic
// camera that maps one world unit to one pixel. Text shares those pixels.
#include "debugdraw/primitives.h"
#include "render/camera.h"
#include "render/image.h"

namespace physdbg::viewer {

inline debugdraw::Vec3 pixelPoint(double x, double y) { return {x, -y, 0.0}; }

inline render::Camera pixelCamera(int width, int height) {
  render::Camera camera;
  camera.orthographic = true;
  camera.orthoHeight = height;
  camera.target = {0.5 * width, -0.5 * height, 0.0};
  camera.eye = camera.target + Eigen::Vector3d(0, 0, 50);
  camera.up = {0, 1, 0};
  return camera;
}

// A filled axis-aligned rectangle, centre and half sizes in pixels.
inline debugdraw::SolidBox pixelRectangle(double x, double y, double halfWidth, double halfHeight,
                                          debugdraw::Color color) {
  return {pixelPoint(x, y), debugdraw::Quat::Identity(), {halfWidth, halfHeight, 0.5}, color};
}

// Places `right` to the right of `left`; the taller one sets the height and the
// gap is filled with the left image's top-left pixel.
render::Image sideBySide(const render::Image& left, const render::Image& right);

}  // namespace physdbg::viewer
