// PNG encoding with libpng's full API (the simplified API cannot choose the
// filter or level) and decoding with its simplified API, which catches
// libpng's longjmps itself and converts every PNG format to RGBA. For writing,
// libpng reports errors by longjmp, so the jump target lives in a function
// that owns nothing. Encoding goes to memory and the file is written apart,
// so encoders on several threads can still write their files in frame order.
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

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  bytes->insert(bytes->end(), data, data + length);
}

void flushNothing(png_structp) {}

// Returns false after a libpng error; `rows` point into the image.
bool encode(png_structp png, png_infop info, std::vector<std::uint8_t>& bytes, const Image& image, int level,
            png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, &bytes, appendBytes, flushNothing);
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

// Owns libpng's decoding state on every path out: libpng frees it after its
// own errors, this frees it after ours (the size limit, a failed allocation).
struct PngDecoder {
  png_image image;
  PngDecoder() {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
  }
  ~PngDecoder() { png_image_free(&image); }
  PngDecoder(const PngDecoder&) = delete;
  PngDecoder& operator=(const PngDecoder&) = delete;
};

// Checked in 64 bits from the header alone, before the pixels are allocated.
void checkSize(const png_image& header, const std::string& name) {
  const std::uint64_t pixels = std::uint64_t{header.width} * header.height;
  if (header.width <= maxImageSide && header.height <= maxImageSide && pixels <= maxImagePixels) return;
  throw std::runtime_error("cannot read PNG '" + name + "': " + std::to_string(header.width) + "x" +
                           std::to_string(header.height) + " pixels is over the limit of " +
                           std::to_string(maxImageSide) + " a side and " + std::to_string(maxImagePixels) +
                           " in all");
}

Image finishRead(png_image& decoder, const std::string& name) {
  checkSize(decoder, name);
  decoder.format = PNG_FORMAT_RGBA;
  decoder.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;  // else 16-bit files are taken as linear and brightened
  Image image;
  image.width = static_cast<int>(decoder.width);
  image.height = static_cast<int>(decoder.height);
  image.rgba.resize(static_cast<std::size_t>(decoder.width) * decoder.height * 4);
  if (!png_image_finish_read(&decoder, nullptr, image.rgba.data(), 0, nullptr))
    throw std::runtime_error("cannot decode PNG '" + name + "': " + decoder.message);
  return image;
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& image, int compressionLevel) {
  validate(image, compressionLevel);
  PngErrorState errorState;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errorState, onPngError, onPngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y)
    rows[y] = const_cast<png_bytep>(image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4);
  // About 60 KB for a debug frame at 1280x720; one reservation saves the regrowth.
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.rgba.size() / 16 + 1024);
  const bool ok = info != nullptr && encode(png, info, bytes, image, compressionLevel, rows.data());
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error(std::string("cannot encode PNG: ") + errorState.message);
  return bytes;
}

void writePngBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw std::runtime_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
  const int writeError = errno;
  const bool closed = std::fclose(file.release()) == 0;
  if (!written) throw std::runtime_error("cannot write PNG '" + path + "': " + std::strerror(writeError));
  if (!closed) throw std::runtime_error("cannot write PNG '" + path + "': close failed: " + std::strerror(errno));
}

void writePng(const std::string& path, const Image& image, int compressionLevel) {
  writePngBytes(path, encodePng(image, compressionLevel));
}

Image readPng(const std::string& path) {
  PngDecoder decoder;
  if (!png_image_begin_read_from_file(&decoder.image, path.c_str()))
    throw std::runtime_error("cannot read PNG '" + path + "': " + decoder.image.message);
  return finishRead(decoder.image, path);
}

Image readPngBytes(std::string_view bytes, const std::string& name) {
  PngDecoder decoder;
  if (!png_image_begin_read_from_memory(&decoder.image, bytes.data(), bytes.size()))
    throw std::runtime_error("cannot read PNG '" + name + "': " + decoder.image.message);
  return finishRead(decoder.image, name);
}

}  // namespace physdbg::render
