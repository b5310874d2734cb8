#pragma once
// A short fingerprint of a scene for approval records: when a check fails,
// the record tells whether the scene file changed since the frames were
// approved. Not a security measure: 64-bit FNV-1a, as 16 hex digits.
#include <filesystem>
#include <string>

namespace physdbg::golden {

std::string textHash(const std::string& text);
// Throws std::runtime_error when the file cannot be read.
std::string fileHash(const std::filesystem::path& path);

}  // namespace physdbg::golden
