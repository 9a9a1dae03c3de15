// The one error type users see: a single line saying what went wrong, where, and what to do.
#pragma once

#include <stdexcept>
#include <string>

namespace wp {

// Thrown for any failure the user can act on (bad file, bad flag, missing device). The
// message is printed as "wavepath: error: <message>" and the program exits non-zero.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A flag that is well-formed but does not fit the rest (a region outside the image, samples
// past --spp), found after parsing: reported like a parse error (exit code 2).
class FlagError : public Error {
public:
  using Error::Error;
};

}  // namespace wp
