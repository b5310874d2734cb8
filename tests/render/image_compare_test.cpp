// compareImages/diffImage on synthetic images: exact match, noise below the
// threshold, one-pixel line shifts, vanished lines, shares, sizes, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "render/image_compare.h"

namespace physdbg::render {
namespace {

constexpr std::uint8_t kBackground[4] = {28, 31, 36, 255};

Image blank(int width = 64, int height = 48) {
  Image image{width, height, {}};
  for (int i = 0; i < width * height; ++i) image.rgba.insert(image.rgba.end(), kBackground, kBackground + 4);
  return image;
}

void setPixel(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* pixel = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  pixel[0] = r, pixel[1] = g, pixel[2] = b;
}

// A one-pixel-wide vertical yellow line at column x.
Image withLine(int x) {
  Image image = blank();
  for (int y = 5; y < 40; ++y) setPixel(image, x, y, 255, 230, 25);
  return image;
}

TEST(ImageCompare, SameBytesAreIdentical) {
  const CompareResult result = compareImages(withLine(10), withLine(10));
  EXPECT_TRUE(result.identical);
  EXPECT_TRUE(result.passed);
  EXPECT_EQ(result.pixelCount, 64u * 48u);
  EXPECT_EQ(result.different, 0u);
}

TEST(ImageCompare, NoiseAtTheThresholdPassesAndAboveFails) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> noise(-8, 8);
  const Image expected = withLine(10);
  Image actual = expected;
  for (std::size_t i = 0; i < actual.rgba.size(); i += 4)
    for (int channel = 0; channel < 3; ++channel)
      actual.rgba[i + channel] = static_cast<std::uint8_t>(std::clamp(actual.rgba[i + channel] + noise(random), 0, 255));
  const CompareResult result = compareImages(expected, actual);
  EXPECT_FALSE(result.identical);
  EXPECT_TRUE(result.passed);
  EXPECT_EQ(result.aboveThreshold, 0u);
  EXPECT_LE(result.maxChannelDifference, 8);
  EXPECT_FALSE(compareImages(expected, actual, {7, 0.0, 0}).passed);  // same noise, tighter threshold
}

TEST(ImageCompare, LineMovedByOnePixelPassesOnlyWithTheNeighbourhood) {
  const CompareResult shifted = compareImages(withLine(10), withLine(11));
  EXPECT_TRUE(shifted.passed);
  EXPECT_EQ(shifted.aboveThreshold, 2u * 35u);  // old and new column
  EXPECT_EQ(shifted.shifted, 2u * 35u);
  EXPECT_FALSE(compareImages(withLine(10), withLine(11), {8, 2e-4, 0}).passed);
  EXPECT_FALSE(compareImages(withLine(10), withLine(12)).passed);  // two pixels is a move
}

TEST(ImageCompare, VanishedLineFailsInBothDirections) {
  EXPECT_FALSE(compareImages(withLine(10), blank()).passed);
  EXPECT_FALSE(compareImages(blank(), withLine(10)).passed);
  EXPECT_EQ(compareImages(withLine(10), blank()).different, 35u);
}

TEST(ImageCompare, ShareOfDifferentPixelsDecides) {
  Image actual = blank();
  for (int x = 0; x < 3; ++x) setPixel(actual, 20 + 3 * x, 20, 250, 20, 20);  // 3 isolated pixels of 3072
  const double share = 3.0 / (64 * 48);
  EXPECT_TRUE(compareImages(blank(), actual, {8, share, 1}).passed);
  EXPECT_FALSE(compareImages(blank(), actual, {8, share * 0.99, 1}).passed);
  EXPECT_NEAR(compareImages(blank(), actual).differentShare(), share, 1e-15);
}

TEST(ImageCompare, DifferentSizesNeverMatch) {
  const CompareResult result = compareImages(blank(64, 48), blank(64, 47), {8, 1.0, 1});
  EXPECT_FALSE(result.sizeMatches);
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.different, 64u);  // the missing row
  EXPECT_EQ(diffImage(blank(64, 48), blank(60, 50)).width, 64);
  EXPECT_EQ(diffImage(blank(64, 48), blank(60, 50)).height, 50);
}

// Sizes that differ are reported as such, every read stays inside its image
// (empty, one pixel, a row, a column), and a diff whose union of extents would
// be huge is refused rather than allocated.
TEST(ImageCompare, SizeMismatchIsAClearErrorNeverAnOutOfBoundsRead) {
  const CompareResult result = compareImages(blank(64, 48), blank(64, 47));
  EXPECT_FALSE(result.passed);
  const std::string figures = describeComparison(result);
  EXPECT_NE(figures.find("DIFFERENT (sizes differ: expected 64x48, actual 64x47)"), std::string::npos) << figures;
  const std::vector<Image> shapes = {blank(0, 0), blank(1, 1), blank(64, 1), blank(1, 48), blank(64, 48)};
  for (const Image& expected : shapes)
    for (const Image& actual : shapes) {
      const CompareResult pair = compareImages(expected, actual);
      const std::size_t width = std::max(expected.width, actual.width), height = std::max(expected.height, actual.height);
      EXPECT_EQ(pair.pixelCount, width * height);
      EXPECT_EQ(pair.passed, expected.width == actual.width && expected.height == actual.height);
      const Image diff = diffImage(expected, actual);
      EXPECT_EQ(diff.rgba.size(), width * height * 4);
    }
  const Image wide = blank(static_cast<int>(maxImageSide) + 1, 1), tall = blank(1, 8193);  // union over maxImagePixels
  EXPECT_THROW(diffImage(wide, tall), std::invalid_argument);
}

TEST(ImageCompare, BadInputThrows) {
  Image broken = blank();
  broken.rgba.pop_back();
  EXPECT_THROW(compareImages(broken, blank()), std::invalid_argument);
  EXPECT_THROW(compareImages(blank(), blank(), {256, 0.1, 1}), std::invalid_argument);
  EXPECT_THROW(compareImages(blank(), blank(), {8, -0.1, 1}), std::invalid_argument);
  EXPECT_THROW(compareImages(blank(), blank(), {8, std::nan(""), 1}), std::invalid_argument);
  EXPECT_THROW(compareImages(blank(), blank(), {8, 0.1, 9}), std::invalid_argument);
  EXPECT_THROW(diffImage(broken, blank()), std::invalid_argument);
}

TEST(ImageCompare, DiffMarksEachKindOfPixel) {
  Image expected = withLine(10);
  Image actual = withLine(11);
  setPixel(actual, 40, 20, 250, 20, 20);                                // different
  setPixel(actual, 50, 20, kBackground[0] + 3, kBackground[1], kBackground[2]);  // below threshold
  const Image diff = diffImage(expected, actual);
  auto at = [&](int x, int y) { return &diff.rgba[(static_cast<std::size_t>(y) * diff.width + x) * 4]; };
  EXPECT_EQ(at(40, 20)[0], 255);
  EXPECT_EQ(at(40, 20)[1], 30);
  EXPECT_EQ(at(11, 20)[1], 210);                 // shifted: yellow
  EXPECT_GT(at(50, 20)[2], 96);                  // amplified blue
  EXPECT_LT(at(0, 0)[0], 16);                    // equal: dimmed background
  EXPECT_EQ(at(0, 0)[0], at(0, 0)[2]);           // grey
  const std::string figures = describeComparison(compareImages(expected, actual));
  EXPECT_NE(figures.find("DIFFERENT"), std::string::npos) << figures;
  EXPECT_NE(describeComparison(compareImages(expected, expected)).find("identical"), std::string::npos);
}

}  // namespace
}  // namespace physdbg::render
