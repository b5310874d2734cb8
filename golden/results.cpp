#include "golden/results.h"

#include <stdexcept>

namespace physdbg::golden {

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Passed: return "passed";
    case Verdict::Failed: return "failed";
    case Verdict::Skipped: return "skipped";
  }
  return "failed";
}

Verdict parseVerdict(const std::string& name) {
  for (const Verdict verdict : {Verdict::Passed, Verdict::Failed, Verdict::Skipped})
    if (name == verdictName(verdict)) return verdict;
  throw std::invalid_argument("expected passed, failed or skipped, got '" + name + "'");
}

Verdict combinedVerdict(const std::vector<FrameResult>& frames) {
  bool skipped = false;
  for (const FrameResult& frame : frames) {
    if (frame.verdict == Verdict::Failed) return Verdict::Failed;
    skipped = skipped || frame.verdict == Verdict::Skipped;
  }
  return skipped ? Verdict::Skipped : Verdict::Passed;
}

Tally tally(const std::vector<CaseResult>& results) {
  Tally counts;
  for (const CaseResult& result : results) {
    if (result.verdict == Verdict::Passed) ++counts.passed;
    if (result.verdict == Verdict::Failed) ++counts.failed;
    if (result.verdict == Verdict::Skipped) ++counts.skipped;
  }
  return counts;
}

}  // namespace physdbg::golden
