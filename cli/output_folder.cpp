#include "cli/output_folder.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace physdbg::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t maxFileNameLength = 64;

bool isPlainNameCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

// The frame number of a file framePath could have written, or -1: "frame_",
// five or more digits without a superfluous leading zero, ".png".
int frameNumber(const std::string& fileName) {
  const std::string prefix = "frame_", suffix = ".png";
  if (fileName.size() < prefix.size() + 5 + suffix.size() || !fileName.starts_with(prefix) ||
      !fileName.ends_with(suffix))
    return -1;
  const std::string digits = fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
  if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  const int number = std::stoi(digits);
  return fs::path(framePath("", number)).filename() == fileName ? number : -1;
}

}  // namespace

UsageError outputError(const std::string& option, const std::string& path, const std::string& reason) {
  const std::string why = !reason.empty() ? reason : errno != 0 ? std::strerror(errno) : "the write failed";
  return UsageError(option + ": cannot write '" + path + "': " + why);
}

void prepareOutputDirectory(const std::string& directory, const std::string& option) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw UsageError(option + ": cannot create folder '" + directory + "'" + (error ? ": " + error.message() : ""));
  const fs::path probe = fs::path(directory) / ".physdbg-write-test";
  {
    std::ofstream file(probe);
    if (!file) throw UsageError(option + ": folder '" + directory + "' is not writable");
  }
  fs::remove(probe, error);
}

void checkOutputFile(const std::string& path, const std::string& option) {
  if (path.empty()) throw UsageError(option + ": the path is empty");
  std::error_code error;
  if (fs::is_directory(path, error)) throw outputError(option, path, "it is a folder");
  const bool existed = fs::exists(path, error);
  errno = 0;
  {
    std::ofstream file(path, std::ios::app);  // appending leaves an existing file as it is
    if (!file) throw outputError(option, path);
  }
  if (!existed) fs::remove(path, error);
}

void writeOutputPng(const std::string& path, const render::Image& image, const std::string& option) {
  try {
    render::writePng(path, image);
  } catch (const std::runtime_error& failure) {
    throw UsageError(option + ": " + failure.what());
  }
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

int removeFrames(const std::string& directory, int first, int last, const std::string& option) {
  std::vector<fs::path> stale;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const int number = frameNumber(entry.path().filename().string());
    std::error_code kind;
    if (number >= first && number < last && !entry.is_directory(kind)) stale.push_back(entry.path());
  }
  if (error) throw UsageError(option + ": cannot list folder '" + directory + "': " + error.message());
  for (const fs::path& path : stale) {
    if (!fs::remove(path, error) && error)
      throw UsageError(option + ": cannot remove '" + path.string() + "' left by an earlier run: " + error.message());
  }
  return static_cast<int>(stale.size());
}

}  // namespace physdbg::cli
