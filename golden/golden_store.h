#pragma once
// Where goldens live. llvmpipe is repeatable for one Mesa version but not
// across versions, so goldens are keyed by renderer and Mesa version:
// tests/golden/mesa-22.3.6-llvmpipe/ for the project's own, and
// MANIFEST_DIR/golden/mesa-22.3.6-llvmpipe/CASE/ for `physdbg golden`. A
// machine whose key has no folder skips the golden comparisons instead of
// failing them falsely.
#include <filesystem>
#include <string>

#include "render/renderer.h"

namespace physdbg::golden {

// "llvmpipe (LLVM 15.0.6, 256 bits)" + "4.5 (Core Profile) Mesa 22.3.6" ->
// "mesa-22.3.6-llvmpipe". Without "Mesa" in the version the whole version is
// used. Characters outside [a-z0-9.] become '-'. Throws std::invalid_argument
// when either string is empty.
std::string goldenKey(const render::GlIdentity& identity);

// ROOT/KEY/NAME.png: the project's goldens, one picture per case.
std::filesystem::path goldenPath(const std::filesystem::path& root, const std::string& key,
                                 const std::string& caseName);

// ROOT/KEY/CASE: a manifest case's approved frames and approval record.
std::filesystem::path caseFolder(const std::filesystem::path& root, const std::string& key,
                                 const std::string& caseName);
// frame_00010.png: the name `physdbg render` gives frame 10, so an approved
// frame can be set beside `render --frames 10:11` output by its name.
std::string frameFileName(int frame);

}  // namespace physdbg::golden
