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

}  // namespace wp
