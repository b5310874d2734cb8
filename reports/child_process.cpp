#include "reports/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

extern char** environ;

namespace physdbg {
namespace {

bool isExecutableFile(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// posix_spawn's file actions, destroyed on every path.
class SpawnActions {
 public:
  explicit SpawnActions(const std::string& program) : program_(program) {
    check(posix_spawn_file_actions_init(&actions_));
  }
  ~SpawnActions() { posix_spawn_file_actions_destroy(&actions_); }
  SpawnActions(const SpawnActions&) = delete;
  SpawnActions& operator=(const SpawnActions&) = delete;

  void open(int descriptor, const char* path, int flags) {
    check(posix_spawn_file_actions_addopen(&actions_, descriptor, path, flags, 0));
  }
  void changeDirectory(const std::string& directory) {
    check(posix_spawn_file_actions_addchdir_np(&actions_, directory.c_str()));
  }
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  void check(int error) const {
    if (error != 0) throw std::runtime_error("cannot start '" + program_ + "': " + std::strerror(error));
  }
  std::string program_;
  posix_spawn_file_actions_t actions_{};
};

// The program as an absolute path: a bare name is looked up on PATH, and a
// relative path must survive the child's change of folder.
std::string resolveProgram(const ChildCommand& command) {
  std::optional<std::string> path;
  if (command.program.find('/') == std::string::npos) {
    path = findExecutable(command.program);
  } else if (isExecutableFile(command.program)) {
    path = std::filesystem::absolute(command.program).string();
  }
  if (!path) throw std::runtime_error("cannot start '" + command.program + "': no such executable");
  return *path;
}

void redirectStandardStreams(const ChildCommand& command, SpawnActions& actions) {
  actions.open(STDIN_FILENO, "/dev/null", O_RDONLY);
  if (command.quiet) {
    actions.open(STDOUT_FILENO, "/dev/null", O_WRONLY);
    actions.open(STDERR_FILENO, "/dev/null", O_WRONLY);
  }
  if (!command.workingDirectory.empty()) actions.changeDirectory(command.workingDirectory);
}

ChildExit exitFromStatus(int status) {
  ChildExit result;
  if (WIFEXITED(status)) {
    result.exited = true;
    result.code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  return result;
}

}  // namespace

std::optional<std::string> findExecutable(const std::string& program) {
  if (program.empty()) return std::nullopt;
  if (program.find('/') != std::string::npos) return isExecutableFile(program) ? std::optional(program) : std::nullopt;
  const char* variable = std::getenv("PATH");
  const std::string folders = variable ? variable : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= folders.size()) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::string folder = folders.substr(start, end - start);
    start = end + 1;
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / program;
    if (isExecutableFile(candidate.string())) return std::filesystem::absolute(candidate).string();
  }
  return std::nullopt;
}

std::string ChildExit::describe() const {
  return exited ? "exit code " + std::to_string(code) : "signal " + std::to_string(signal);
}

ChildProcess::ChildProcess(const ChildCommand& command) {
  const std::string program = resolveProgram(command);
  SpawnActions actions(command.program);
  redirectStandardStreams(command, actions);
  std::vector<std::string> words{program};
  words.insert(words.end(), command.arguments.begin(), command.arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const int error = posix_spawn(&pid_, program.c_str(), actions.get(), nullptr, argv.data(), environ);
  if (error != 0) {
    pid_ = -1;
    throw std::runtime_error("cannot start '" + command.program + "': " + std::strerror(error));
  }
}

ChildProcess::~ChildProcess() {
  if (pid_ <= 0 || exit_) return;
  ::kill(pid_, SIGTERM);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
}

ChildExit ChildProcess::wait() {
  if (exit_) return *exit_;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0) {
    if (errno == EINTR) continue;
    const int error = errno;
    pid_ = -1;  // nothing left to reap or to stop
    throw std::runtime_error(std::string("waiting for a child process failed: ") + std::strerror(error));
  }
  exit_ = exitFromStatus(status);
  return *exit_;
}

ChildExit runChild(const ChildCommand& command) { return ChildProcess(command).wait(); }

}  // namespace physdbg
