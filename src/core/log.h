// Warnings and notes on stderr, in one format, so users and tests can rely on them.
#pragma once

#include <string>

namespace wp {

// Prints "wavepath: warning: <message>" on stderr.
void warn(const std::string& message);
// Prints "wavepath: note: <message>" on stderr.
void note(const std::string& message);

}  // namespace wp
