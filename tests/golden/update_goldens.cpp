// Regenerates the golden PNGs for this machine's renderer key after an
// intended change: golden_update ROOT writes ROOT/KEY/CASE.png for every case
// and removes PNGs of cases that no longer exist. Run it through
// scripts/update-goldens.sh, which fixes LP_NUM_THREADS.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <set>

#include "golden/golden_store.h"
#include "tests/golden/golden_cases.h"
#include "viewer/frame_renderer.h"

namespace fs = std::filesystem;
using namespace physdbg;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: golden_update GOLDEN_ROOT (normally tests/golden)\n");
    return 2;
  }
  try {
    render::Renderer renderer({golden::kWidth, golden::kHeight, 0});
    const std::string key = golden::goldenKey(renderer.glIdentity());
    fs::create_directories(fs::path(argv[1]) / key);
    std::set<fs::path> written;
    for (const golden::GoldenCase& golden : golden::goldenCases()) {
      const fs::path path = golden::goldenPath(argv[1], key, golden.name);
      const render::Image image = golden::renderGoldenCase(golden, renderer);
      render::writePng(path.string(), image, 9);
      written.insert(path);
      std::printf("wrote %s (%ju bytes)\n", path.c_str(), static_cast<std::uintmax_t>(fs::file_size(path)));
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(argv[1]) / key))
      if (entry.path().extension() == ".png" && !written.count(entry.path())) {
        fs::remove(entry.path());
        std::printf("removed stale %s\n", entry.path().c_str());
      }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "golden_update: %s\n", error.what());
    return 1;
  }
  return 0;
}
