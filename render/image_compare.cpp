#include "render/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace physdbg::render {
namespace {

constexpr int kMaxRadius = 8;

enum class PixelVerdict { Equal, Close, Shifted, Different };

void validate(const Image& image, const char* which) {
  if (image.width < 0 || image.height < 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::invalid_argument(std::string("compareImages: ") + which + " image has " +
                                std::to_string(image.rgba.size()) + " bytes for " + std::to_string(image.width) +
                                "x" + std::to_string(image.height) + " RGBA pixels");
}

void validate(const CompareOptions& options) {
  if (options.channelThreshold < 0 || options.channelThreshold > 255)
    throw std::invalid_argument("compareImages: channel threshold must be in 0..255, got " +
                                std::to_string(options.channelThreshold));
  if (!(options.maxDifferentShare >= 0 && options.maxDifferentShare <= 1))
    throw std::invalid_argument("compareImages: maximum share of different pixels must be in 0..1");
  if (options.neighbourhoodRadius < 0 || options.neighbourhoodRadius > kMaxRadius)
    throw std::invalid_argument("compareImages: neighbourhood radius must be in 0.." + std::to_string(kMaxRadius) +
                                ", got " + std::to_string(options.neighbourhoodRadius));
}

bool inside(const Image& image, int x, int y) { return x >= 0 && y >= 0 && x < image.width && y < image.height; }

const std::uint8_t* pixel(const Image& image, int x, int y) {
  return image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
}

int channelDifference(const std::uint8_t* a, const std::uint8_t* b) {
  int largest = 0;
  for (int channel = 0; channel < 4; ++channel) largest = std::max(largest, std::abs(a[channel] - b[channel]));
  return largest;
}

// Whether `image` has a pixel within `radius` of (x, y) that matches `colour`.
bool matchNearby(const Image& image, int x, int y, const std::uint8_t* colour, const CompareOptions& options) {
  const int radius = options.neighbourhoodRadius;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (inside(image, x + dx, y + dy) && channelDifference(pixel(image, x + dx, y + dy), colour) <= options.channelThreshold)
        return true;
  return false;
}

PixelVerdict judge(const Image& expected, const Image& actual, int x, int y, const CompareOptions& options,
                   int& difference) {
  difference = 0;
  if (!inside(expected, x, y) || !inside(actual, x, y)) return PixelVerdict::Different;
  const std::uint8_t* want = pixel(expected, x, y);
  const std::uint8_t* got = pixel(actual, x, y);
  difference = channelDifference(want, got);
  if (difference == 0) return PixelVerdict::Equal;
  if (difference <= options.channelThreshold) return PixelVerdict::Close;
  if (options.neighbourhoodRadius > 0 && matchNearby(actual, x, y, want, options) &&
      matchNearby(expected, x, y, got, options))
    return PixelVerdict::Shifted;
  return PixelVerdict::Different;
}

template <typename Visit>
void forEachPixel(const Image& expected, const Image& actual, const CompareOptions& options, Visit visit) {
  validate(expected, "expected");
  validate(actual, "actual");
  validate(options);
  const int width = std::max(expected.width, actual.width), height = std::max(expected.height, actual.height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int difference = 0;
      const PixelVerdict verdict = judge(expected, actual, x, y, options, difference);
      visit(x, y, verdict, difference);
    }
}

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::uint8_t clampLevel(double value) { return static_cast<std::uint8_t>(std::clamp(value, 0.0, 255.0)); }

}  // namespace

CompareResult compareImages(const Image& expected, const Image& actual, const CompareOptions& options) {
  validate(expected, "expected");
  validate(actual, "actual");
  validate(options);
  CompareResult result;
  result.expectedWidth = expected.width, result.expectedHeight = expected.height;
  result.actualWidth = actual.width, result.actualHeight = actual.height;
  result.sizeMatches = expected.width == actual.width && expected.height == actual.height;
  if (result.sizeMatches && expected.rgba == actual.rgba) {  // the exact hash-like check comes first
    result.identical = result.passed = true;
    result.pixelCount = static_cast<std::size_t>(expected.width) * expected.height;
    return result;
  }
  forEachPixel(expected, actual, options, [&](int, int, PixelVerdict verdict, int difference) {
    ++result.pixelCount;
    result.maxChannelDifference = std::max(result.maxChannelDifference, difference);
    if (verdict == PixelVerdict::Shifted || verdict == PixelVerdict::Different) ++result.aboveThreshold;
    if (verdict == PixelVerdict::Shifted) ++result.shifted;
    if (verdict == PixelVerdict::Different) ++result.different;
  });
  result.passed = result.sizeMatches && result.differentShare() <= options.maxDifferentShare;
  return result;
}

Image diffImage(const Image& expected, const Image& actual, const CompareOptions& options) {
  Image diff;
  diff.width = std::max(expected.width, actual.width);
  diff.height = std::max(expected.height, actual.height);
  if (static_cast<std::uint64_t>(diff.width) * static_cast<std::uint64_t>(diff.height) > maxImagePixels)
    throw std::invalid_argument("diffImage: the union of " + sizeText(expected.width, expected.height) + " and " +
                                sizeText(actual.width, actual.height) + " is over the limit of " +
                                std::to_string(maxImagePixels) + " pixels");
  diff.rgba.assign(static_cast<std::size_t>(diff.width) * diff.height * 4, 255);
  forEachPixel(expected, actual, options, [&](int x, int y, PixelVerdict verdict, int difference) {
    std::uint8_t* out = diff.rgba.data() + (static_cast<std::size_t>(y) * diff.width + x) * 4;
    double grey = 0;
    if (inside(expected, x, y)) {
      const std::uint8_t* source = pixel(expected, x, y);
      grey = 0.25 * (0.299 * source[0] + 0.587 * source[1] + 0.114 * source[2]);
    }
    switch (verdict) {
      case PixelVerdict::Equal: out[0] = out[1] = out[2] = clampLevel(grey); break;
      case PixelVerdict::Close:  // amplified so that a 1-level difference is visible
        out[0] = out[1] = clampLevel(grey);
        out[2] = clampLevel(96 + 159.0 * difference / std::max(1, options.channelThreshold));
        break;
      case PixelVerdict::Shifted: out[0] = 255, out[1] = 210, out[2] = 0; break;
      case PixelVerdict::Different: out[0] = 255, out[1] = 30, out[2] = 30; break;
    }
  });
  return diff;
}

std::string describeComparison(const CompareResult& result, const CompareOptions& options) {
  char line[512];
  if (result.identical) {
    std::snprintf(line, sizeof line, "identical: %zu pixels, same bytes", result.pixelCount);
    return line;
  }
  const std::string sizes = result.sizeMatches ? ""
                                               : " (sizes differ: expected " +
                                                     sizeText(result.expectedWidth, result.expectedHeight) +
                                                     ", actual " + sizeText(result.actualWidth, result.actualHeight) +
                                                     ")";
  std::snprintf(line, sizeof line,
                "%s%s: %zu of %zu pixels differ by more than %d levels (largest %d); %zu of them within %d px of a "
                "match; %zu different = %.4f%% (allowed %.4f%%)",
                result.passed ? "match" : "DIFFERENT", sizes.c_str(),
                result.aboveThreshold, result.pixelCount, options.channelThreshold, result.maxChannelDifference,
                result.shifted, options.neighbourhoodRadius, result.different, 100.0 * result.differentShare(),
                100.0 * options.maxDifferentShare);
  return line;
}

}  // namespace physdbg::render
