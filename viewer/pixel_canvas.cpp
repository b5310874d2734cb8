#include "viewer/pixel_canvas.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace physdbg::viewer {

render::Image sideBySide(const render::Image& left, const render::Image& right) {
  for (const render::Image* image : {&left, &right})
    if (image->width <= 0 || image->height <= 0 ||
        image->rgba.size() != static_cast<std::size_t>(image->width) * image->height * 4)
      throw std::invalid_argument("sideBySide: inconsistent image");
  render::Image result;
  result.width = left.width + right.width;
  result.height = std::max(left.height, right.height);
  result.rgba.resize(static_cast<std::size_t>(result.width) * result.height * 4);
  for (std::size_t i = 0; i < result.rgba.size(); i += 4) std::memcpy(&result.rgba[i], left.rgba.data(), 4);
  auto paste = [&](const render::Image& image, int column) {
    for (int row = 0; row < image.height; ++row)
      std::memcpy(&result.rgba[(static_cast<std::size_t>(row) * result.width + column) * 4],
                  &image.rgba[static_cast<std::size_t>(row) * image.width * 4], static_cast<std::size_t>(image.width) * 4);
  };
  paste(left, 0);
  paste(right, left.width);
  return result;
}

}  // namespace physdbg::viewer
