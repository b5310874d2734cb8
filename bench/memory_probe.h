#pragma once
// Peak memory of a piece of work, as the operating system counts it: the
// peak resident set above the floor (pages touched, allocator slack and
// freed-but-kept blocks included), not what the allocator says is in use.
//
// The work runs in a child process forked for it: the child hands its free
// heap back to the kernel (malloc_trim), resets the kernel's peak (writing 5
// to /proc/self/clear_refs), reads its resident set as the floor, runs the
// work, and reports VmHWM less the floor through a pipe. Measured in the
// parent, work would reuse pages an earlier benchmark freed and the
// allocator kept resident, and read low. fork copies only the calling
// thread: the work must not need the parent's other threads.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace physdbg::bench {

// Returns what `work` returned in the child, with "peak_bytes" and
// "floor_bytes" added. Throws std::runtime_error naming `what` when the
// child fails or work throws (its message is passed on).
nlohmann::json measureInChild(const std::string& what, const std::function<nlohmann::json()>& work);

}  // namespace physdbg::bench
