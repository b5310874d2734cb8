#pragma once
// Image comparison for golden-image tests: exact bytes first, then a tolerant
// comparison that absorbs software-rasteriser noise but not real changes.
//
// A pixel differs when one of its RGBA channels differs by more than
// `channelThreshold` levels. A differing pixel is still accepted as "shifted"
// when both images have a matching pixel (within the threshold) within
// `neighbourhoodRadius` of it, in both directions: a thin line moved by one
// pixel passes, a line that vanished does not (its colour has no match nearby
// in the other image). The images match when the share of differing,
// non-shifted pixels is at most `maxDifferentShare`.
//
// Defaults: llvmpipe on other CPUs differs by 2-3 levels per channel
// (approximate reciprocals), so 8 levels leaves margin while a colour change a
// person can see (>= 10 levels) is caught. 0.0002 of a 320x240 frame is 15
// pixels: less than one 6-pixel contact point (36 pixels) or a box moved by
// one pixel along a 20-pixel edge.
#include <cstddef>
#include <string>

#include "render/image.h"

namespace physdbg::render {

struct CompareOptions {
  int channelThreshold = 8;         // levels 0..255 per channel
  double maxDifferentShare = 2e-4;  // of the larger image's pixel count, 0..1
  int neighbourhoodRadius = 1;      // pixels, 0 disables the allowance
};

struct CompareResult {
  bool identical = false;   // same size and same bytes
  bool sizeMatches = false;
  int expectedWidth = 0, expectedHeight = 0, actualWidth = 0, actualHeight = 0;
  bool passed = false;
  std::size_t pixelCount = 0;      // of the union of both images' extents
  std::size_t aboveThreshold = 0;  // pixels with a channel difference above the threshold
  std::size_t shifted = 0;         // of those, accepted by the neighbourhood allowance
  std::size_t different = 0;       // above the threshold and not shifted
  int maxChannelDifference = 0;    // over the overlapping pixels
  double differentShare() const { return pixelCount ? double(different) / double(pixelCount) : 0.0; }
};

// Throws std::invalid_argument for options out of range (threshold outside
// 0..255, share outside 0..1 or NaN, radius outside 0..8) or an image whose
// byte count does not match its size. Images of different sizes never match
// (a golden test still wants to see where they differ): pixels outside either
// image count as different, and every read is inside its image.
CompareResult compareImages(const Image& expected, const Image& actual, const CompareOptions& options = {});

// A picture of the differences, the size of the union of both extents: the
// expected image dimmed to grey, differences below the threshold in amplified
// blue, shifted pixels in yellow, different pixels in red. Same validation as
// compareImages; also refuses a union of extents over maxImagePixels (a wide
// and a tall image), which could be far larger than either image.
Image diffImage(const Image& expected, const Image& actual, const CompareOptions& options = {});

// One line of figures for people: "identical: ..." or "match/DIFFERENT: N of
// M pixels differ by more than T levels (largest L); S of them within R px of
// a match; D different = P% (allowed Q%)", with "(sizes differ: expected WxH,
// actual WxH)" after the verdict when they do.
std::string describeComparison(const CompareResult& result, const CompareOptions& options = {});

}  // namespace physdbg::render
