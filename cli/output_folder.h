#pragma once
// Output folders and frame file names shared by the commands that write
// frame sequences, so split renders of one scene land in one folder.
#include <string>

namespace physdbg::cli {

// Creates the folder and checks it is writable before any work is done.
// Throws UsageError (exit code 2) naming the folder.
void prepareOutputDirectory(const std::string& directory);

// DIR/frame_00042.png: the global frame index, whatever range a run renders.
std::string framePath(const std::string& directory, int index);

}  // namespace physdbg::cli
