// Warnings and notes on stderr.
#include "core/log.h"

#include <cstdio>

namespace wp {

void warn(const std::string& message) { std::fprintf(stderr, "wavepath: warning: %s\n", message.c_str()); }

void note(const std::string& message) { std::fprintf(stderr, "wavepath: note: %s\n", message.c_str()); }

}  // namespace wp
