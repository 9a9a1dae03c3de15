// Checks for number flags whose messages say what the number must be: CLI11's NonNegativeNumber
// and PositiveNumber print their range up to the largest double ("not in range 0.000000 to
// 179769313486231570814527..."). Whether the text is a finite number at all is checked before
// these, for every float flag (requireFiniteNumbers, command_line.cpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace wp {

inline CLI::Validator zeroOrMore() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        return CLI::detail::lexical_cast(text, value) && value >= 0.0 ? "" : "'" + text + "' must be 0 or more";
      },
      "NONNEGATIVE");
}

inline CLI::Validator moreThanZero() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        return CLI::detail::lexical_cast(text, value) && value > 0.0 ? "" : "'" + text + "' must be more than 0";
      },
      "POSITIVE");
}

}  // namespace wp
