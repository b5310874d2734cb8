#pragma once
// What `render`, `record` and `replay` draw (viewer/view_options.h), read
// from their shared options (cli/common_options.h) and checked against the
// scene before any work.
#include "cli/arguments.h"
#include "cli/common_options.h"
#include "scenes/scene.h"

namespace physdbg::cli {

using viewer::selectionOf;

// The camera, --highlight, --labels and --samples: what a replay can still
// choose. With a scene, --follow and --highlight bodies are checked against it.
void readDrawChoices(const Arguments& arguments, ViewOptions& options, const SceneDescription* scene = nullptr);

// Every view option of a scene run. Throws UsageError for bad values,
// including a --follow or --highlight body the scene lacks.
ViewOptions readViewOptions(const Arguments& arguments, const SceneDescription& scene);

}  // namespace physdbg::cli
