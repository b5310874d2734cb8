#pragma once
// Approving and checking one manifest case against the store next to its
// manifest, MANIFEST_DIR/golden/KEY/CASE/ (frame_NNNNN.png and approved.json;
// KEY: golden_store.h). The command runs cases here one by one, or each in a
// process of its own (golden check -j), with the same result either way.
#include <filesystem>
#include <string>
#include <vector>

#include "golden/case_frames.h"
#include "golden/manifest.h"
#include "golden/results.h"

namespace physdbg::golden {

// MANIFEST_DIR/golden.
std::filesystem::path storeRoot(const Manifest& manifest);

// Where a case's pictures go in a report, relative to its root: cases/CASE
// (beside index.html, so no case name can take the page's place).
std::filesystem::path reportCaseFolder(const std::string& caseName);

// Renders the case and stores its frames and approval record, removing
// approved frames the case no longer lists. Returns the files written.
// Throws std::runtime_error when they cannot be written.
std::vector<std::filesystem::path> approveCase(const ManifestCase& golden, RendererPool& renderers,
                                               const std::filesystem::path& store);

// Renders the case and compares each frame with its approved one. Skipped,
// without rendering, when this renderer key has no approved frames at all;
// failed when the key has some but not this case's, or a frame is missing.
// With a report root, pictures of failed frames go to REPORT/cases/CASE/frame_NNNNN/.
CaseResult checkCase(const ManifestCase& golden, RendererPool& renderers, const std::filesystem::path& store,
                     const std::filesystem::path& reportRoot);

// "scene 'drop.json', 320x240, layers shapes,aabbs", for reports.
std::string describeCase(const ManifestCase& golden);

}  // namespace physdbg::golden
