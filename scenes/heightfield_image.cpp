#include "scenes/heightfield_image.h"

#include <png.h>

#include <memory>

namespace physdbg {
namespace {

// png_image owns libpng's state until finished or freed.
struct ImageReader {
  png_image image{};
  ImageReader() { image.version = PNG_IMAGE_VERSION; }
  ~ImageReader() { png_image_free(&image); }
  ImageReader(const ImageReader&) = delete;
  ImageReader& operator=(const ImageReader&) = delete;
};

}  // namespace

HeightfieldImage readHeightfieldImage(const std::string& path, std::uint64_t maxSamples) {
  ImageReader reader;
  png_image& image = reader.image;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw HeightfieldImageError(std::string("libpng cannot read it: ") + image.message);
  // A file of 8-bit samples would come back gamma-decoded, and 256 levels
  // are steps, not terrain: only 16-bit grayscale is taken.
  if ((image.format & PNG_FORMAT_FLAG_LINEAR) == 0 || (image.format & PNG_FORMAT_FLAG_COLOR) != 0)
    throw HeightfieldImageError("it is not a 16-bit grayscale PNG");
  const std::uint64_t samples = std::uint64_t{image.width} * image.height;
  if (samples > maxSamples)
    throw HeightfieldImageError("it is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                " samples (at most " + std::to_string(maxSamples) + ")");
  image.format = PNG_FORMAT_LINEAR_Y;
  std::vector<png_uint_16> pixels(static_cast<std::size_t>(samples));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr))
    throw HeightfieldImageError(std::string("libpng cannot read it: ") + image.message);
  HeightfieldImage out;
  out.columns = static_cast<int>(image.width);
  out.rows = static_cast<int>(image.height);
  out.heights.assign(pixels.begin(), pixels.end());
  return out;
}

}  // namespace physdbg
