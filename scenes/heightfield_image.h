#pragma once
// Heights from a 16-bit grayscale PNG, read with libpng (already the
// renderer's encoder): what terrain tools export. Each pixel is one sample,
// 0 to 65535, rows down the image running along +z.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace physdbg {

class HeightfieldImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HeightfieldImage {
  int columns = 0, rows = 0;
  std::vector<float> heights;  // rows x columns, row by row
};

// Throws HeightfieldImageError (without the path) for a file libpng cannot
// read, an image that is not 16-bit grayscale, or more than maxSamples
// pixels (checked from the header, before the pixels are read).
HeightfieldImage readHeightfieldImage(const std::string& path, std::uint64_t maxSamples);

}  // namespace physdbg
