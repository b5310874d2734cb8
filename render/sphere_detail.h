#pragma once
// Level of detail for spheres, capsules and arrow heads. A full-detail sphere costs ~1000
// triangles, which llvmpipe cannot afford a thousand times per frame, so each
// instance gets the coarsest mesh whose silhouette stays within 3/4 of a
// pixel (smooth normals hide the facets inside): a polygon of s sides deviates
// from a circle of radius r pixels by r (1 - cos(pi / s)) ~ r pi^2 / (2 s^2).
#include <array>
#include <vector>

#include "render/camera.h"
#include "render/frame_batches.h"

namespace physdbg::render {

inline constexpr std::array<int, 7> kSphereSegments = {8, 12, 16, 24, 32, 48, 64};

// Index into kSphereSegments for a sphere of the given radius in pixels.
int sphereDetailLevel(double radiusPixels);

// Projects instance radii (scale.x) to pixels for a viewport `heightPixels`
// high and splits the instances by level, keeping frame order within a level.
std::array<std::vector<Instance>, kSphereSegments.size()> splitByDetail(const std::vector<Instance>& instances,
                                                                         const Camera& camera, int heightPixels);

// Arrow heads are flat-shaded cones, their facets lit apart, so the coarse
// cone is kept to heads whose base is at most kCoarseConeRadiusPixels: its
// silhouette then stays within half a pixel of the fine one's. Most heads of a
// debug picture are a few pixels (a resting contact's normal spans 12).
inline constexpr int kCoarseConeSegments = 8, kFineConeSegments = 16;
inline constexpr double kCoarseConeRadiusPixels = 6;

struct ConesByDetail {
  std::vector<Instance> coarse, fine;  // frame order within each
};

// Splits arrow heads (cone instances, base radius scale.x at the translation).
ConesByDetail splitConesByDetail(const std::vector<Instance>& heads, const Camera& camera, int heightPixels);

}  // namespace physdbg::render
