#pragma once
// Recordings: the debug-draw primitive stream of a run, so frames can be
// rendered later, elsewhere, or in pieces, without the engine. Format
// (version 1, all numbers little-endian, documented in debugdraw/RECORDING.md):
//   "PHYSDBGR" u32 version, then chunks: u32 tag, u64 payload bytes, payload.
//   tag 1 mesh: written once before the first frame that uses it.
//   tag 2 frame: i32 frame index, the view, then each primitive list.
// Readers skip chunks with unknown tags, and frame payloads outside the
// requested range without decoding them.
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>

#include "debugdraw/primitives.h"

namespace physdbg::debugdraw {

inline constexpr std::uint32_t recordingVersion = 1;

// Where a frame was seen from: camera data without any renderer type.
struct View {
  Vec3 eye{0, 0, 10}, target{0, 0, 0}, up{0, 1, 0};
  double fovYDegrees = 45;
  bool orthographic = false;
  double orthoHeight = 10;
};

struct RecordedFrame {
  int index = 0;
  View view;
  Frame frame;
};

class RecordingWriter {
 public:
  // Throws std::runtime_error naming the path when it cannot be created.
  explicit RecordingWriter(const std::string& path);
  void write(const RecordedFrame& recorded);
  // Flushes; throws std::runtime_error when any write failed (disk full).
  void close();

 private:
  void writeChunk(std::uint32_t tag, const std::string& payload);
  std::string path_;
  std::ofstream file_;
  std::set<std::uint64_t> meshesWritten_;
};

class RecordingReader {
 public:
  // Throws std::invalid_argument naming the path for a missing file, a file
  // that is not a recording, or a newer version.
  explicit RecordingReader(const std::string& path);
  // Next frame whose index is in [first, last); false at the end of the file.
  // Throws std::invalid_argument for a truncated or corrupt file.
  bool next(RecordedFrame& out, int first = 0, int last = std::numeric_limits<int>::max());

 private:
  std::string path_;
  std::ifstream file_;
  std::map<std::uint64_t, std::shared_ptr<const TriangleMesh>> meshes_;
};

}  // namespace physdbg::debugdraw
