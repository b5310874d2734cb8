#include "cli/arguments.h"

#include <charconv>
#include <cmath>
#include <iostream>
#include <sstream>

namespace physdbg::cli {

std::optional<Arguments> Arguments::parse(const CommandSpec& spec, const std::vector<std::string>& args) {
  Arguments result;
  result.command_ = spec.name;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << helpText(spec);
      return std::nullopt;
    }
    if (arg.size() > 1 && arg[0] == '-' && !(arg.size() > 1 && (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.'))) {
      std::string name = arg, inlineValue;
      bool hasInlineValue = false;
      if (const auto equals = arg.find('='); equals != std::string::npos && arg.rfind("--", 0) == 0) {
        name = arg.substr(0, equals);
        inlineValue = arg.substr(equals + 1);
        hasInlineValue = true;
      }
      const OptionSpec* option = nullptr;
      for (const OptionSpec& candidate : spec.options) {
        if (candidate.name == name || (!candidate.shortName.empty() && candidate.shortName == name)) option = &candidate;
      }
      if (!option) throw UsageError("unknown option '" + name + "' (see physdbg " + spec.name + " --help)");
      if (option->valueName.empty()) {
        if (hasInlineValue) throw UsageError(option->name + " takes no value");
        result.values_[option->name] = "";
        continue;
      }
      if (!hasInlineValue) {
        if (i + 1 >= args.size()) throw UsageError(option->name + " needs a value " + option->valueName);
        inlineValue = args[++i];
      }
      result.values_[option->name] = inlineValue;
      continue;
    }
    result.positional_.push_back(arg);
  }
  const int count = static_cast<int>(result.positional_.size());
  if (count < spec.minPositional) throw UsageError("missing argument (usage: physdbg " + spec.name + " " + spec.usage + ")");
  if (count > spec.maxPositional)
    throw UsageError("unexpected argument '" + result.positional_[spec.maxPositional] + "' (usage: physdbg " +
                     spec.name + " " + spec.usage + ")");
  return result;
}

std::string Arguments::value(const std::string& option, const std::string& fallback) const {
  const auto found = values_.find(option);
  return found == values_.end() ? fallback : found->second;
}

int Arguments::positiveInt(const std::string& option, int fallback, int maximum) const {
  if (!has(option)) return fallback;
  const std::string text = value(option);
  int parsed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (error != std::errc() || end != text.data() + text.size() || parsed <= 0 || parsed > maximum)
    throw UsageError(option + " must be a whole number from 1 to " + std::to_string(maximum) + ", got '" + text + "'");
  return parsed;
}

double Arguments::positiveDouble(const std::string& option, double fallback) const {
  if (!has(option)) return fallback;
  const std::string text = value(option);
  double parsed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (error != std::errc() || end != text.data() + text.size() || !(parsed > 0) || !std::isfinite(parsed))
    throw UsageError(option + " must be a positive number, got '" + text + "'");
  return parsed;
}

std::string helpText(const CommandSpec& spec) {
  std::ostringstream text;
  text << "usage: physdbg " << spec.name << " " << spec.usage << "\n\n" << spec.summary << "\n";
  if (!spec.options.empty()) text << "\noptions:\n";
  for (const OptionSpec& option : spec.options) {
    std::string left = "  " + (option.shortName.empty() ? "" : option.shortName + ", ") + option.name;
    if (!option.valueName.empty()) left += " " + option.valueName;
    if (left.size() < 28) left.resize(28, ' ');
    else left += "  ";
    text << left << option.help << "\n";
  }
  std::string help = "  -h, --help";
  help.resize(28, ' ');
  text << help << "show this help\n";
  return text.str();
}

}  // namespace physdbg::cli
