#pragma once
// Helpers shared by the recording tests: byte patches of encoded recordings,
// and decoding with a count of what it allocated, so hostile-input tests can
// check that limits are enforced before anything is allocated for them.
// The allocation counter is fed by the operator new that
// recording_format_test.cpp replaces (not in sanitizer builds: they count nothing).
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "debugdraw/recording.h"

namespace physdbg::recordingtesting {

namespace dd = physdbg::debugdraw;
namespace fs = std::filesystem;

extern thread_local bool countAllocations;
extern thread_local std::size_t allocatedBytes;

inline std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("physdbg-recording-" + std::to_string(::getpid()) + "-" + name)).string();
}

inline std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline std::string recordingBytes(const std::vector<dd::RecordedFrame>& frames) {
  const std::string path = tempPath("bytes");
  dd::RecordingWriter writer(path);
  for (const dd::RecordedFrame& frame : frames) writer.write(frame);
  writer.close();
  std::string bytes = fileBytes(path);
  fs::remove(path);
  return bytes;
}

template <typename Number>
std::string bitsOf(Number value) {
  std::string bits(sizeof value, '\0');
  std::memcpy(bits.data(), &value, sizeof value);
  return bits;
}

template <typename Number>
Number numberAt(const std::string& bytes, std::size_t at) {
  Number value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

template <typename Number>
void putNumber(std::string& bytes, std::size_t at, Number value) {
  bytes.replace(at, sizeof value, bitsOf(value));
}

inline std::string chunkHead(std::uint32_t tag, std::uint64_t size) { return bitsOf(tag) + bitsOf(size); }

inline void expectMentions(const std::string& message, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}

// Counts the bytes this thread allocates while it lives.
class AllocationCount {
 public:
  AllocationCount() {
    allocatedBytes = 0;
    countAllocations = true;
  }
  ~AllocationCount() { countAllocations = false; }
  AllocationCount(const AllocationCount&) = delete;
  AllocationCount& operator=(const AllocationCount&) = delete;
  std::size_t bytes() const { return allocatedBytes; }
};

struct Decoded {
  std::size_t frames = 0;
  bool refused = false;  // with std::invalid_argument; anything else fails the test
  std::string message;
  std::size_t allocated = 0;
};

inline Decoded decodeBytes(std::string bytes, const std::string& name = "hostile.rec") {
  Decoded decoded;
  const AllocationCount count;
  try {
    decoded.frames = dd::readRecordingBytes(std::move(bytes), name).size();
  } catch (const std::invalid_argument& error) {
    decoded.refused = true;
    decoded.message = error.what();
  }
  decoded.allocated = count.bytes();
  return decoded;
}

}  // namespace physdbg::recordingtesting
