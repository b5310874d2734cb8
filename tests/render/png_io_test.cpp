#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <stdexcept>

#include "render/image.h"

namespace physdbg::render {
namespace {

Image randomImage(int width, int height, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
  for (auto& value : image.rgba) value = static_cast<std::uint8_t>(byte(generator));
  return image;
}

std::string temporaryPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("physdbg_png_test_" + name)).string();
}

TEST(PngIo, RoundTripIsExactAtEveryLevel) {
  const Image image = randomImage(37, 23, 7);  // odd sizes catch stride mistakes
  for (int level : {0, 1, 9}) {
    const std::string path = temporaryPath("roundtrip.png");
    writePng(path, image, level);
    const Image back = readPng(path);
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
    EXPECT_EQ(back.rgba, image.rgba) << "level " << level;
    std::filesystem::remove(path);
  }
}

TEST(PngIo, UnwritablePathThrowsNamingThePath) {
  const std::string path = "/nonexistent-directory-physdbg/picture.png";
  try {
    writePng(path, randomImage(4, 4, 1));
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

TEST(PngIo, MissingFileThrowsNamingThePath) {
  const std::string path = temporaryPath("does_not_exist.png");
  try {
    readPng(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

TEST(PngIo, InconsistentImageIsRejected) {
  Image image = randomImage(4, 4, 2);
  image.rgba.pop_back();
  EXPECT_THROW(writePng(temporaryPath("bad.png"), image), std::invalid_argument);
  EXPECT_THROW(writePng(temporaryPath("bad.png"), Image{}), std::invalid_argument);
  EXPECT_THROW(writePng(temporaryPath("bad.png"), randomImage(2, 2, 3), 10), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::render
