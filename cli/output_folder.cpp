#include "cli/output_folder.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/arguments.h"

namespace physdbg::cli {

namespace fs = std::filesystem;

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

std::string framePath(const std::string& directory, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return (fs::path(directory) / name).string();
}

}  // namespace physdbg::cli
