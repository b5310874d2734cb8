#pragma once
// A stage of a step timed by scope (step_profile.h).
#include <chrono>

namespace physdbg {

// Adds the seconds from its construction to its end to `into`.
class StageTimer {
 public:
  explicit StageTimer(double& into) : into_(into), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double& into_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace physdbg
