#pragma once
// Pictures a test renders, kept for a person to look at: written to the folder
// named by PHYSDBG_TEST_PICTURES when it is set, never otherwise, so test runs
// leave nothing behind by default.
#include <cstdlib>
#include <string>

#include "render/image.h"

namespace physdbg::render::testing {

inline void keepPicture(const Image& image, const std::string& name) {
  const char* folder = std::getenv("PHYSDBG_TEST_PICTURES");
  if (folder && *folder) writePng(std::string(folder) + "/" + name, image);
}

}  // namespace physdbg::render::testing
