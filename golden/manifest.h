#pragma once
// A manifest of a user's golden cases (README.md, "physdbg golden"):
//   {"cases": [{"name": "drop", "scene": "scenes/drop.json", "frames": [0, 10, 30],
//               "size": "320x240", "layers": "shapes,aabbs,contacts",
//               "camera": {"eye": [6, 4, 8], "target": [0, 1, 0]}, "solver": "seed"}]}
// Manifests come from other people and run in CI: everything is read and
// checked here, scenes loaded included, before anything is drawn; every
// number is bounded (golden/manifest_limits.h), unknown keys are refused
// (a misspelt "layer" must not silently draw the default layers), and case
// names, which become folder names, are plain names, never paths. It reads
// JSON as scene files are read (scenes/json_reader.h: bounded size and
// nesting, short excerpts of hostile values in messages).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "debugdraw/primitives.h"
#include "scenes/scene.h"
#include "viewer/view_options.h"

namespace physdbg::golden {

struct ManifestCase {
  std::string name;
  std::string sceneName;   // as the manifest names it: a built-in scene or a path from the manifest's folder
  SceneDescription scene;  // loaded, with the case's solver applied
  std::string sceneHash;   // content_hash of the scene file, or of "builtin:NAME"
  std::vector<int> frames;  // increasing
  int width = 320, height = 240;
  std::string layers;  // as given, else the scene's, else render's default
  viewer::CameraOptions camera;
  std::optional<SolverKind> solver;
};

struct Manifest {
  std::filesystem::path file;
  std::filesystem::path folder;  // scene paths and the golden/ store are relative to it
  std::vector<ManifestCase> cases;
};

// Throws SceneError, as the scene loader does for scene files (exit code 2),
// naming the file, the key and the problem: "golden.json: cases[2].frames: ...".
Manifest readManifest(const std::filesystem::path& file);

// Case names are [A-Za-z0-9_.-], 1..64 characters, not starting with '.':
// safe as a folder name on every system. False for "../../x", "a/b", "".
bool isValidCaseName(const std::string& name);

}  // namespace physdbg::golden
