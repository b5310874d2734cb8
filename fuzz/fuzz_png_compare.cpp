// Fuzz target: the two PNGs `physdbg compare` and the golden tests read. The
// input is split in two images; each decodes or is refused with
// std::runtime_error, and two decoded images compare, describe and diff
// without reading outside either.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "render/image.h"
#include "render/image_compare.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace physdbg::render;
  if (size < 2) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t split = 1 + data[0] % (size - 1);  // the first byte chooses where the second image starts
  try {
    const Image expected = readPngBytes(bytes.substr(1, split - 1), "expected.png");
    const Image actual = readPngBytes(bytes.substr(split), "actual.png");
    const CompareResult result = compareImages(expected, actual);
    describeComparison(result);
    diffImage(expected, actual);
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
