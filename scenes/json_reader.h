#pragma once
// Typed, validated reads from a parsed scene file. Every failure throws
// SceneError naming the file and the key path ("drop.json: bodies[3].mass:
// ..."), and quotes at most a short excerpt of the offending value or key, so
// a hostile file cannot blow up the message. Only the scene loader includes
// this (nlohmann/json is a heavy header).
#include <array>
#include <cstddef>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/math.h"

namespace physdbg {

// "abc" for short texts, "abcd... (50000000 bytes)" for long ones.
std::string excerpt(const std::string& text);
// A number as messages show it (ostream's default: "1e+09", "0.5").
std::string formatNumber(double value);

// Parses JSON text after checking what a parser would not: its size, NUL
// bytes and nesting depth (deep nesting overflows recursive consumers).
nlohmann::json parseBoundedJson(const std::string& text, const std::string& source);

class JsonReader {
 public:
  using json = nlohmann::json;

  explicit JsonReader(std::string source) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  void requireObject(const json& value, const std::string& path) const;
  void checkKeys(const json& object, const std::string& path, const std::set<std::string>& allowed) const;
  // `path.key` with the key shortened when it is long.
  static std::string child(const std::string& path, const std::string& key);

  // Finite, at most scene_limits::maxMagnitude in size.
  double number(const json& value, const std::string& path) const;
  // Positive and at least scene_limits::minSize: lengths, masses.
  double size(const json& value, const std::string& path) const;
  double nonNegative(const json& value, const std::string& path) const;
  double inRange(const json& value, const std::string& path, double low, double high) const;
  long long integer(const json& value, const std::string& path, long long low, long long high) const;
  bool boolean(const json& value, const std::string& path) const;
  std::string string(const json& value, const std::string& path) const;
  const json& array(const json& value, const std::string& path, std::size_t length) const;
  Vec3 vec3(const json& value, const std::string& path) const;
  Vec3 sizeVec3(const json& value, const std::string& path) const;
  Quat quaternion(const json& value, const std::string& path) const;
  std::array<bool, 3> bool3(const json& value, const std::string& path) const;

  // A member that must be present.
  const json& required(const json& object, const std::string& path, const char* key) const;

 private:
  double finite(const json& value, const std::string& path) const;
  std::string source_;
};

}  // namespace physdbg
