// Checks for number flags whose messages say what the number must be: CLI11's NonNegativeNumber
// and PositiveNumber print their range up to the largest double ("not in range 0.000000 to
// 179769313486231570814527..."). Whether the text is a finite number at all is checked before
// these, for every float flag (requireFiniteNumbers, command_line.cpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace wp {

// Accepts a number above 0, or with `zeroAllowed` of 0 or more.
inline CLI::Validator lowerBoundCheck(bool zeroAllowed) {
  return CLI::Validator(
      [zeroAllowed](std::string& text) -> std::string {
        double value = 0.0;
        const bool parsed = CLI::detail::lexical_cast(text, value);
        if (parsed && (value > 0.0 || (zeroAllowed && value == 0.0))) return "";
        return "'" + text + (zeroAllowed ? "' must be 0 or more" : "' must be more than 0");
      },
      zeroAllowed ? "NONNEGATIVE" : "POSITIVE");
}

inline CLI::Validator zeroOrMore() { return lowerBoundCheck(true); }
inline CLI::Validator moreThanZero() { return lowerBoundCheck(false); }

}  // namespace wp
