// Fuzz target: a recording file from a stranger. Decoding must either give
// frames or throw std::invalid_argument naming the problem; never crash and
// never allocate past the limits in debugdraw/RECORDING.md.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "debugdraw/recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    physdbg::debugdraw::readRecordingBytes(std::string(reinterpret_cast<const char*>(data), size), "fuzz.rec");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
