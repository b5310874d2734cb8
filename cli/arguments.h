#pragma once
// A small command-line parser: each subcommand declares its options, and
// anything else is a usage error (exit code 2) that names the argument.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace physdbg::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  std::string name;       // "--frames"
  std::string shortName;  // "-o" or empty
  std::string valueName;  // empty for a flag
  std::string help;
};

struct CommandSpec {
  std::string name;
  std::string usage;  // after "physdbg NAME "
  std::string summary;
  std::vector<OptionSpec> options;
  int minPositional = 0, maxPositional = 0;
};

class Arguments {
 public:
  // Throws UsageError for unknown options, missing values or a wrong number of
  // positional arguments. Returns nullopt when --help was asked for (and prints it).
  static std::optional<Arguments> parse(const CommandSpec& spec, const std::vector<std::string>& args);

  bool has(const std::string& option) const { return values_.count(option) != 0; }
  std::string value(const std::string& option, const std::string& fallback = "") const;
  const std::vector<std::string>& positional() const { return positional_; }

  // Typed accessors: throw UsageError naming the option and the bad value.
  // Whole numbers 1..maximum (the bound keeps loops and allocations finite).
  int positiveInt(const std::string& option, int fallback, int maximum) const;
  double positiveDouble(const std::string& option, double fallback) const;

 private:
  std::string command_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
};

std::string helpText(const CommandSpec& spec);

// Runs `call`, reporting the viewer's std::invalid_argument (viewer/ knows no
// UsageError: a degenerate camera, an unwritable frame) as a UsageError with
// the same message.
template <typename Call>
decltype(auto) asUsageError(Call&& call) {
  try {
    return call();
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

}  // namespace physdbg::cli
