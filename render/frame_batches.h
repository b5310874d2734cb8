#pragma once
// A Frame flattened into float arrays ready for upload, positions relative to
// `origin` (the camera target): subtracting in double before converting to
// float keeps a scene at 1e7 m as precise as one at the origin.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "debugdraw/primitives.h"

namespace physdbg::render {

// Per-instance data of the instanced shaders (boxes, spheres, capsules, meshes,
// arrow heads, wire boxes). scale.w is the capsule half height.
struct Instance {
  float translation[3];
  float rotation[4];  // unit quaternion x, y, z, w
  float scale[4];
  float color[4];
};

struct ColoredVertex {
  float position[3];
  float color[4];
};

struct PointVertex {
  float position[3];
  float size;
  float color[4];
};

// Screen-space text vertex in pixels from the top-left corner.
struct TextVertex {
  float position[2];
  float color[4];
};

// Solid meshes sharing one TriangleMesh, in order of first appearance.
struct MeshBatch {
  const debugdraw::TriangleMesh* mesh = nullptr;
  std::vector<Instance> instances;
};

// Arrows and points are markers: the renderer draws them over the solids
// with a dark outline, so they are kept apart from the plain lines.
struct FrameBatches {
  std::vector<Instance> boxes, spheres, capsules, arrowHeads, wireBoxes;
  std::vector<MeshBatch> meshes;
  std::vector<ColoredVertex> lines;        // pairs
  std::vector<ColoredVertex> arrowShafts;  // pairs
  std::vector<PointVertex> points;
  std::vector<TextVertex> texts;  // triangles: labels' outlines, their glyphs, then the same for texts
};

// Where positions relative to the origin land in the image. Given one,
// buildFrameBatches lengthens arrows shorter than kMinimumArrowPixels on
// screen (keeping start and direction): a resting contact normal or a slow
// body's velocity would otherwise be a few pixels, unreadable.
struct ScreenMapping {
  Eigen::Matrix4d viewProjection;  // of positions relative to the origin
  double width = 0, height = 0;    // pixels
};
inline constexpr double kMinimumArrowPixels = 12;
inline constexpr double kMinimumArrowHeadPixels = 5;

// Labels become screen-space text placed over their projected anchors; those
// outside the view or behind the eye, and all of them without a screen, draw
// nothing. Throws std::invalid_argument for non-finite positions, negative
// sizes, a zero quaternion, a solid mesh without mesh, a non-positive text or
// label scale, or more than maxFrameTextCharacters in texts and labels together.
FrameBatches buildFrameBatches(const debugdraw::Frame& frame, const Eigen::Vector3d& origin,
                               const ScreenMapping* screen = nullptr);

}  // namespace physdbg::render
