#include "golden/content_hash.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace physdbg::golden {
namespace {

constexpr std::uint64_t kOffset = 14695981039346656037ull, kPrime = 1099511628211ull;

void mix(std::uint64_t& hash, const char* bytes, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) hash = (hash ^ static_cast<unsigned char>(bytes[i])) * kPrime;
}

std::string hex(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace

std::string textHash(const std::string& text) {
  std::uint64_t hash = kOffset;
  mix(hash, text.data(), text.size());
  return hex(hash);
}

std::string fileHash(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot read '" + path.string() + "'");
  std::uint64_t hash = kOffset;
  std::array<char, 65536> buffer{};
  while (file.read(buffer.data(), buffer.size()) || file.gcount() > 0)
    mix(hash, buffer.data(), static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw std::runtime_error("cannot read '" + path.string() + "'");
  return hex(hash);
}

}  // namespace physdbg::golden
