#include "bench/memory_probe.h"

#include <fcntl.h>
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace physdbg::bench {
namespace {

// A "Key:   123 kB" line of /proc/self/status, in bytes; throws if absent.
double statusBytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key + ":", 0) == 0) return 1024.0 * std::stod(line.substr(key.size() + 1));
  }
  throw std::runtime_error("/proc/self/status has no " + key);
}

// The floor, with free heap returned and the peak reset.
double resetToFloor() {
  malloc_trim(0);
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.close();
  if (!clear) throw std::runtime_error("cannot reset the peak through /proc/self/clear_refs");
  return statusBytes("VmRSS");
}

nlohmann::json runInChild(const std::function<nlohmann::json()>& work) {
  try {
    const double floor = resetToFloor();
    nlohmann::json result = work();
    result["peak_bytes"] = statusBytes("VmHWM") - floor;
    result["floor_bytes"] = floor;
    return result;
  } catch (const std::exception& error) {
    return {{"error", error.what()}};
  }
}

void writeAll(int fd, const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t count = ::write(fd, text.data() + written, text.size() - written);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) return;
    written += static_cast<std::size_t>(count);
  }
}

std::string readAll(int fd) {
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t count = ::read(fd, buffer, sizeof buffer);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) break;
    text.append(buffer, static_cast<std::size_t>(count));
  }
  return text;
}

std::runtime_error failure(const std::string& what, const std::string& why) {
  return std::runtime_error("bench memory: " + what + ": " + why);
}

}  // namespace

nlohmann::json measureInChild(const std::string& what, const std::function<nlohmann::json()>& work) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) throw failure(what, std::string("pipe: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(ends[0]);
    ::close(ends[1]);
    throw failure(what, std::string("fork: ") + std::strerror(error));
  }
  if (child == 0) {
    ::close(ends[0]);
    writeAll(ends[1], runInChild(work).dump());
    ::_exit(0);  // no destructors or exit handlers of the parent's state
  }
  ::close(ends[1]);
  const std::string text = readAll(ends[0]);
  ::close(ends[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty())
    throw failure(what, "the child process failed (wait status " + std::to_string(status) + ")");
  nlohmann::json result = nlohmann::json::parse(text, nullptr, false);
  if (result.is_discarded()) throw failure(what, "the child's report is not JSON");
  if (result.contains("error")) throw failure(what, result["error"].get<std::string>());
  return result;
}

}  // namespace physdbg::bench
