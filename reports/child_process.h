#pragma once
// Runs another program (ffmpeg) from an argument vector, never
// through a shell. Scene names and paths come from other people: passed as
// separate arguments, quotes, semicolons and spaces stay literal text and
// can never start a command.
//
// It lives in reports/, which the physdbg command (ffmpeg) links, because the
// accuracy report once ran gnuplot through it; plots are now drawn by
// viewer/line_plot. It needs nothing but POSIX.
#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace physdbg {

// The absolute path of the executable `program` in the folders of $PATH, or
// nullopt. Empty PATH entries are skipped rather than read as the current
// folder. A name with a '/' is checked as given.
std::optional<std::string> findExecutable(const std::string& program);

struct ChildCommand {
  std::string program;                 // a path, or a name looked up with findExecutable
  std::vector<std::string> arguments;  // argv[1], argv[2], ...
  std::string workingDirectory;        // empty: ours
  bool quiet = false;                  // discard the child's stdout and stderr
};

// How a child ended.
struct ChildExit {
  bool exited = false;  // false: killed by `signal`
  int code = -1;
  int signal = 0;
  bool succeeded() const { return exited && code == 0; }
  std::string describe() const;  // "exit code 1", "signal 9"
};

// A started child. Its standard input is /dev/null: a run in CI has no
// keyboard, and ffmpeg would otherwise read commands from ours. If it is
// destroyed without wait() (an exception on the way), the child is
// terminated and reaped, so no path leaves it running or a zombie.
class ChildProcess {
 public:
  // Throws std::runtime_error naming the program when it cannot be started.
  explicit ChildProcess(const ChildCommand& command);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  ChildExit wait();
  pid_t id() const { return pid_; }

 private:
  pid_t pid_ = -1;
  std::optional<ChildExit> exit_;
};

// Starts `command` and waits for it.
ChildExit runChild(const ChildCommand& command);

}  // namespace physdbg
