#pragma once
// A hash of every body's state, bit for bit: two runs that print the same hash
// produced the same doubles.
#include <cstdint>
#include <string>

namespace physdbg {
class World;
}

namespace physdbg::cli {

std::uint64_t worldStateHash(const World& world);
std::string hexHash(std::uint64_t hash);

}  // namespace physdbg::cli
