#pragma once
// Helpers for the physdbg command tests that need more than runPhysdbg: a
// run in a chosen folder (relative outputs land there) and a fake ffmpeg
// that writes down the arguments it was given.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/visual_test_support.h"
#include "reports/child_process.h"

namespace physdbg::clitesting {

inline void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

inline std::vector<std::string> readLines(const std::string& path) {
  std::ifstream file(path);
  std::vector<std::string> result;
  for (std::string line; std::getline(file, line);) result.push_back(line);
  return result;
}

// PATH with `folder` first, for the lifetime of the object.
class PathPrefix {
 public:
  explicit PathPrefix(const std::string& folder) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", (folder + ":" + old_).c_str(), 1);
  }
  ~PathPrefix() { ::setenv("PATH", old_.c_str(), 1); }
  PathPrefix(const PathPrefix&) = delete;
  PathPrefix& operator=(const PathPrefix&) = delete;

 private:
  std::string old_;
};

// Writes FOLDER/bin/ffmpeg, which writes its arguments one a line to `log`;
// returns FOLDER/bin.
inline std::string fakeFfmpegFolder(const visualtesting::ScratchFolder& folder, const std::string& log) {
  std::filesystem::create_directories(folder / "bin");
  writeFile(folder / "bin/ffmpeg",
            "#!/bin/sh\nfor argument in \"$@\"; do printf '%s\\n' \"$argument\"; done > '" + log + "'\n");
  std::filesystem::permissions(folder / "bin/ffmpeg", std::filesystem::perms::owner_all);
  return folder / "bin";
}

// Runs physdbg in `folder` with an argument vector, output discarded.
inline ChildExit physdbgIn(const std::string& folder, std::vector<std::string> arguments) {
  ChildCommand command;
  command.program = PHYSDBG_BINARY;
  command.arguments = std::move(arguments);
  command.workingDirectory = folder;
  command.quiet = true;
  return runChild(command);
}

}  // namespace physdbg::clitesting
