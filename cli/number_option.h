#pragma once
// A numeric option within a closed range, parsed whole (no trailing text, no
// spaces; from_chars also refuses "nan" against any range): a bad value is a
// UsageError naming the option, the range and the text.
#include <charconv>
#include <string>

#include "cli/arguments.h"

namespace physdbg::cli {

template <typename Number>
Number numberOption(const Arguments& arguments, const std::string& option, Number fallback, Number low, Number high) {
  if (!arguments.has(option)) return fallback;
  const std::string text = arguments.value(option);
  Number parsed{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (error != std::errc() || end != text.data() + text.size() || !(parsed >= low && parsed <= high))
    throw UsageError(option + " must be a number in " + std::to_string(low) + ".." + std::to_string(high) + ", got '" +
                     text + "'");
  return parsed;
}

}  // namespace physdbg::cli
