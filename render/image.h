#pragma once
// An RGBA8 image in memory, rows top to bottom, and its PNG file form.
#include <cstdint>
#include <string>
#include <string_view>
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

// writePng in two halves, byte for byte the same file: the encoding (no file
// touched; throws std::invalid_argument as above) and the write (throws
// std::runtime_error naming the path: a missing folder, a full disk).
std::vector<std::uint8_t> encodePng(const Image& image, int compressionLevel = 1);
void writePngBytes(const std::string& path, const std::vector<std::uint8_t>& bytes);

// PNGs come from other people (`physdbg compare`, golden images), so their
// size is checked from the header before any pixel memory is allocated: at most
// 16384 pixels a side and 128 Mi pixels (512 MiB as RGBA), which still admits
// the largest picture physdbg writes (two 8192x8192 tree panels side by side).
inline constexpr std::uint32_t maxImageSide = 16384;
inline constexpr std::uint64_t maxImagePixels = std::uint64_t{1} << 27;

// Any PNG (grey, grey+alpha, palette, RGB, RGBA; 1 to 16 bits; interlaced or
// not), converted to 8-bit RGBA; 16-bit samples are taken as sRGB like 8-bit
// ones, so 0x8080 becomes 0x80. Throws std::runtime_error naming the path for a
// missing, corrupt or truncated file or one over the limits above.
Image readPng(const std::string& path);

// The same for a PNG held in memory (the fuzzing entry point); `name` stands
// for the path in messages.
Image readPngBytes(std::string_view bytes, const std::string& name);

}  // namespace physdbg::render
