#pragma once
// A one-line progress bar with frames/s and ETA on stderr, shown only when
// stderr is a terminal so logs and CI output stay clean.
#include <chrono>
#include <string>

namespace physdbg::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, int total);
  void update(int done);
  void finish();

 private:
  std::string label_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace physdbg::cli
