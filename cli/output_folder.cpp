#include "cli/output_folder.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/arguments.h"

namespace physdbg::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t maxFileNameLength = 64;

bool isPlainNameCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

}  // namespace

void prepareOutputDirectory(const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw UsageError("-o: cannot create folder '" + directory + "'" + (error ? ": " + error.message() : ""));
  const fs::path probe = fs::path(directory) / ".physdbg-write-test";
  {
    std::ofstream file(probe);
    if (!file) throw UsageError("-o: folder '" + directory + "' is not writable");
  }
  fs::remove(probe, error);
}

std::string safeFileName(const std::string& name) {
  std::string safe;
  for (const char c : name) {
    if (safe.size() == maxFileNameLength) break;
    const bool dotAllowed = c == '.' && !safe.empty() && safe.back() != '.';
    safe += isPlainNameCharacter(c) || dotAllowed ? c : '_';
  }
  return safe.empty() ? "scene" : safe;
}

std::string sceneOutputFolder(const std::string& sceneName, const std::string& prefix) {
  return (fs::path("out") / (prefix + safeFileName(sceneName))).string();
}

std::string framePath(const std::string& directory, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return (fs::path(directory) / name).string();
}

}  // namespace physdbg::cli
