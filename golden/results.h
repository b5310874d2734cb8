#pragma once
// What a golden check found, per frame and per case, as plain data. The HTML
// report, the JUnit file and the result files of cases checked in other
// processes (`golden check -j`, GNU parallel, other machines) are all written
// from these, so a case checked here and one checked elsewhere read the same.
#include <string>
#include <vector>

namespace physdbg::golden {

// Skipped is not passed: nothing was compared (no approved frames for this
// renderer key), and reports say so.
enum class Verdict { Passed, Failed, Skipped };

// "passed", "failed", "skipped".
const char* verdictName(Verdict verdict);
// The inverse; throws std::invalid_argument for another word.
Verdict parseVerdict(const std::string& name);

struct FrameResult {
  std::string label;  // "frame 10"
  Verdict verdict = Verdict::Passed;
  std::string figures;  // the comparison's line (render::describeComparison), or why nothing was compared
  // Folder under the report root with expected.png, actual.png and diff.png;
  // empty when none were written (passed, skipped, or no report asked for).
  std::string images;
};

struct CaseResult {
  std::string name;
  std::string description;  // what was drawn: scene, layers, size
  Verdict verdict = Verdict::Passed;
  std::string message;  // why the case was skipped or failed as a whole, and notes
  std::vector<FrameResult> frames;
  double seconds = 0;
};

// Failed if any frame failed, else skipped if any was skipped, else passed.
Verdict combinedVerdict(const std::vector<FrameResult>& frames);

struct Tally {
  int passed = 0, failed = 0, skipped = 0;
};
Tally tally(const std::vector<CaseResult>& results);

}  // namespace physdbg::golden
