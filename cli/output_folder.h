#pragma once
// Output folders and frame file names shared by the commands that write
// frame sequences, so split renders of one scene land in one folder, and
// the safe folder names made from scene names.
#include <string>

namespace physdbg::cli {

// Creates the folder and checks it is writable before any work is done.
// Throws UsageError (exit code 2) naming the folder.
void prepareOutputDirectory(const std::string& directory);

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

}  // namespace physdbg::cli
