#include <gtest/gtest.h>

#include <malloc.h>

#include <cstring>
#include <fstream>
#include <string>
#include <memory>
#include <vector>

#include "bench/memory_probe.h"

namespace physdbg::bench {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

// Small blocks the allocator keeps in its arena when freed (not mmapped).
std::vector<std::unique_ptr<char[]>> touchBlocks(std::size_t bytes) {
  constexpr std::size_t kBlock = 4096;
  std::vector<std::unique_ptr<char[]>> blocks;
  for (std::size_t done = 0; done < bytes; done += kBlock) {
    blocks.emplace_back(new char[kBlock]);
    std::memset(blocks.back().get(), 1, kBlock);
  }
  return blocks;
}

nlohmann::json touch(std::size_t bytes) {
  const auto blocks = touchBlocks(bytes);
  return {{"blocks", blocks.size()}};
}

TEST(MemoryProbe, SeesWhatTheWorkTouches) {
  const nlohmann::json result = measureInChild("64 MiB", [] { return touch(64 * 1024 * 1024); });
  EXPECT_EQ(result.at("blocks").get<std::size_t>(), 16384u);
  EXPECT_GE(result.at("peak_bytes").get<double>(), 64 * kMiB);
  EXPECT_LE(result.at("peak_bytes").get<double>(), 72 * kMiB);  // 16 bytes of header a block, and the vector
  EXPECT_GT(result.at("floor_bytes").get<double>(), 0.0);
}

TEST(MemoryProbe, IdleWorkMeasuresNearZero) {
  const nlohmann::json result = measureInChild("nothing", [] { return nlohmann::json::object(); });
  EXPECT_LT(result.at("peak_bytes").get<double>(), 2 * kMiB);
}

double residentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return 1024.0 * std::stod(line.substr(6));
  return 0.0;
}

// Memory the parent freed and its allocator kept resident would read as free
// in a child that reuses it: the child returns it to the kernel first.
TEST(MemoryProbe, MemoryTheParentFreedIsNotCountedFree) {
  mallopt(M_TRIM_THRESHOLD, 1 << 30);  // the parent's heap keeps what it frees
  const double before = residentBytes();
  { const auto freed = touchBlocks(64 * 1024 * 1024); }
  ASSERT_GE(residentBytes() - before, 60 * kMiB) << "the parent returned the blocks: this test would prove nothing";
  mallopt(M_TRIM_THRESHOLD, 128 * 1024);  // glibc's default
  const nlohmann::json result = measureInChild("64 MiB again", [] { return touch(64 * 1024 * 1024); });
  EXPECT_GE(result.at("peak_bytes").get<double>(), 60 * kMiB) << result.dump();
}

TEST(MemoryProbe, AFailureInTheChildNamesTheWork) {
  try {
    measureInChild("the failing case", []() -> nlohmann::json { throw std::runtime_error("no room"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("the failing case: no room"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace physdbg::bench
