#pragma once
// Output folders, output files and frame file names shared by every command
// that writes, so that a path a user gave fails the same way everywhere: a
// UsageError (exit code 2) naming the option and the path, before the work
// when it can be seen then, and when the write fails otherwise.
#include <string>

#include "cli/arguments.h"
#include "render/image.h"

namespace physdbg::cli {

// Creates the folder and checks it is writable before any work is done.
// Throws UsageError naming `option` and the folder.
void prepareOutputDirectory(const std::string& directory, const std::string& option = "-o");

// Checks that `path` can be written as a file (its folder exists, it is not a
// folder, it opens for writing) without changing an existing file. Throws
// UsageError naming `option` and the path.
void checkOutputFile(const std::string& path, const std::string& option);

// "--trace: cannot write 'x.csv': No space left on device". Without a
// reason, the one errno gives (clear errno before the write to check).
UsageError outputError(const std::string& option, const std::string& path, const std::string& reason = "");

// writePng, with a failure reported as a UsageError naming `option`.
void writeOutputPng(const std::string& path, const render::Image& image, const std::string& option);

// A scene name as a safe file name: letters, digits, '-', '_' and '.' are
// kept, everything else (slashes, quotes, spaces, bytes of other alphabets)
// becomes '_'; a leading '.' and a second '.' in a row become '_' too, so
// neither "." nor ".." nor a hidden file can come out; at most 64 characters;
// "scene" for an empty name. Scene files come from other people: a name
// like "../../x" must not write outside out/.
std::string safeFileName(const std::string& name);

// out/PREFIXNAME for a scene name (render: out/NAME, tree: out/tree_NAME).
std::string sceneOutputFolder(const std::string& sceneName, const std::string& prefix = "");

// DIR/frame_00042.png: the global frame index, whatever range a run renders.
std::string framePath(const std::string& directory, int index);

// Removes the frame files (names exactly as framePath writes them) numbered
// first..last-1 from `directory`, so frames of an earlier, longer run cannot
// pass for this run's; every other file stays. Returns how many it removed.
// Throws UsageError naming `option` when one cannot be removed.
int removeFrames(const std::string& directory, int first, int last, const std::string& option);

}  // namespace physdbg::cli
