#pragma once
// Recordings: the debug-draw primitive stream of a run, so frames can be
// rendered later, elsewhere, or in pieces, without the engine; with the tags,
// labels and body state a viewer (replay) needs to choose layers, highlight,
// label and follow bodies after the run. Format (version 4, all numbers
// little-endian, documented in debugdraw/RECORDING.md):
//   "PHYSDBGR" u32 version, then chunks: u32 tag, u64 payload bytes, payload.
//   tag 1 mesh: written once before the first frame that uses it.
//   tag 2 frame: u32 frame index (at most 2^31 - 1), the view, then each
//   primitive list (every item followed by its Tag), labels, then bodies.
// Version 1 files (no tags, labels or bodies) still read, with default tags.
// Readers skip chunks with unknown tags, and frame payloads outside the
// requested range without decoding them; every size is checked against the
// bytes left in the file and against the limits below before it is allocated.
#include <cstdint>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "debugdraw/primitives.h"

namespace physdbg::debugdraw {

// What writers write; readers read 1 to 4. Version 4 added the mesh layer's bit.
inline constexpr std::uint32_t recordingVersion = 4;

// Limits (RECORDING.md, "Limits"). Recordings come from other people: a value
// beyond these is corruption or hostile input, refused before anything is
// allocated for it. Writers refuse to write what readers would refuse.
inline constexpr std::uint64_t maxChunkBytes = std::uint64_t{1} << 30;  // 1 GiB
inline constexpr std::uint32_t maxListItems = 1u << 24;                  // per list (bodies too)
inline constexpr std::uint32_t maxMeshVertices = 1u << 24;
inline constexpr std::uint32_t maxMeshIndices = 3u << 24;  // 16 Mi triangles
// Positions and lengths in metres: 1e12 keeps every difference the renderer
// converts to float far inside float range.
inline constexpr double maxCoordinate = 1e12;
inline constexpr float maxPointPixels = 1024;
inline constexpr float minTextScale = 0.001f, maxTextScale = 1000;
inline constexpr float maxTextPixels = 1e6f;  // text position, either axis

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
  // The layers the recording run was asked to show (its --layers): what a
  // replay shows unless told otherwise. The frame may hold more (every layer).
  LayerSet shownLayers{allLayerBits};
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
  // Reads from any seekable stream (bytes in memory: std::istringstream);
  // `name` stands for the path in messages.
  RecordingReader(std::unique_ptr<std::istream> stream, const std::string& name);
  // Next frame whose index is in [first, last); false at the end of the file.
  // Throws std::invalid_argument naming the file (and the byte offset or the
  // frame) for a truncated or corrupt file or a value beyond the limits.
  bool next(RecordedFrame& out, int first = 0, int last = std::numeric_limits<int>::max());
  // The file's format version (1 or 2). Version 1 primitives carry no tags
  // (layer 0, no bodies) and frames no labels or bodies, so a viewer can say
  // why layer or body selection cannot work on it.
  std::uint32_t version() const { return version_; }

 private:
  struct ChunkHead {
    std::uint64_t offset = 0;  // of the chunk in the file
    std::uint32_t tag = 0;
    std::uint64_t size = 0;
  };
  void readHeader();
  ChunkHead readChunkHead();
  bool readFrame(const ChunkHead& head, RecordedFrame& out, int first, int last);
  void readMesh(const ChunkHead& head);
  std::string readBytes(std::uint64_t count);
  void skip(std::uint64_t count);
  std::uint64_t remaining() const { return length_ - offset_; }
  [[noreturn]] void fail(const std::string& what) const;

  std::string name_;
  std::unique_ptr<std::istream> stream_;
  std::uint64_t length_ = 0;  // learnt at open: every chunk size is checked against it
  std::uint64_t offset_ = 0;
  std::uint32_t version_ = 0;
  std::map<std::uint64_t, std::shared_ptr<const TriangleMesh>> meshes_;
};

// Every frame of a recording held in memory, in file order; the entry point
// for fuzzing. Same checks and exceptions as RecordingReader, naming `name`.
std::vector<RecordedFrame> readRecordingBytes(std::string bytes, const std::string& name);

}  // namespace physdbg::debugdraw
