// PNG encoding with libpng's full API (the simplified API cannot choose the
// filter or level) and decoding with its simplified API. libpng reports errors
// by longjmp, so the jump target lives in a function that owns nothing.
#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include "render/image.h"

namespace physdbg::render {
namespace {

struct PngErrorState {
  char message[256] = "unknown libpng error";
};

void onPngError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof(state->message), "%s", message);
  png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

// Returns false after a libpng error; `rows` point into the image.
bool encode(png_structp png, png_infop info, std::FILE* file, const Image& image, int level,
            png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_compression_level(png, level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  return true;
}

void validate(const Image& image, int compressionLevel) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("writePng: image size must be positive");
  if (image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::invalid_argument("writePng: rgba holds " + std::to_string(image.rgba.size()) +
                                " bytes, expected width*height*4");
  if (compressionLevel < 0 || compressionLevel > 9)
    throw std::invalid_argument("writePng: compression level must be in 0..9");
}

}  // namespace

void writePng(const std::string& path, const Image& image, int compressionLevel) {
  validate(image, compressionLevel);
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw std::runtime_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  PngErrorState errorState;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errorState, onPngError, onPngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y)
    rows[y] = const_cast<png_bytep>(image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4);
  const bool ok = info != nullptr && encode(png, info, file.get(), image, compressionLevel, rows.data());
  png_destroy_write_struct(&png, &info);
  const bool closed = std::fclose(file.release()) == 0;
  if (!ok) throw std::runtime_error("cannot write PNG '" + path + "': " + errorState.message);
  if (!closed) throw std::runtime_error("cannot write PNG '" + path + "': close failed");
}

Image readPng(const std::string& path) {
  png_image decoder;
  std::memset(&decoder, 0, sizeof(decoder));
  decoder.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&decoder, path.c_str()))
    throw std::runtime_error("cannot read PNG '" + path + "': " + decoder.message);
  decoder.format = PNG_FORMAT_RGBA;
  Image image;
  image.width = static_cast<int>(decoder.width);
  image.height = static_cast<int>(decoder.height);
  image.rgba.resize(PNG_IMAGE_SIZE(decoder));
  if (!png_image_finish_read(&decoder, nullptr, image.rgba.data(), 0, nullptr)) {
    png_image_free(&decoder);
    throw std::runtime_error("cannot decode PNG '" + path + "': " + decoder.message);
  }
  return image;
}

}  // namespace physdbg::render
