#pragma once
// An RGBA8 image in memory, rows top to bottom, and its PNG file form.
#include <cstdint>
#include <string>
#include <vector>

namespace physdbg::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, rows top to bottom
};

// libpng with the UP filter: level 1 is several times faster than stb's encoder
// at a similar size for debug pictures. Throws std::invalid_argument for an
// inconsistent image or level outside 0..9, std::runtime_error naming the path
// when the file cannot be written.
void writePng(const std::string& path, const Image& image, int compressionLevel = 1);

// Any PNG, converted to 8-bit RGBA. Throws std::runtime_error naming the path.
Image readPng(const std::string& path);

}  // namespace physdbg::render
