#pragma once
// What approved frames were drawn from, stored beside them as
// golden/KEY/CASE/approved.json: the renderer, the physdbg version, the
// scene (and a hash of its file) and the case's settings. A failing check
// then says what changed since approval (the scene file, the layers, the
// version) instead of leaving a person to guess from pictures.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "golden/manifest.h"
#include "render/renderer.h"

namespace physdbg::golden {

struct ApprovalRecord {
  std::string caseName, rendererKey, glRenderer, glVersion, physdbgVersion;
  std::string scene, sceneHash, size, layers, solver;
  std::vector<int> frames;
};

// The version this physdbg was built as (the project's CMake version).
std::string physdbgVersion();

ApprovalRecord approvalRecordOf(const ManifestCase& golden, const std::string& key, const render::GlIdentity& gl);

// Throws std::runtime_error when the file cannot be written.
void writeApprovalRecord(const std::filesystem::path& path, const ApprovalRecord& record);
// nullopt when the file is missing or not a record (an older or hand-made store).
std::optional<ApprovalRecord> readApprovalRecord(const std::filesystem::path& path);

// "the scene file changed since approval (hash A, now B); layers were 'x', now 'y'", or "".
std::string describeChanges(const ApprovalRecord& approved, const ApprovalRecord& now);

}  // namespace physdbg::golden
