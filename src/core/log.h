// Warnings and notes on stderr, in one format, so users and tests can rely on them.
#pragma once

#include <cstddef>
#include <string>

namespace wp {

// Prints "wavepath: warning: <message>" on stderr. Of warnings that differ only in numbers
// and quoted names (one per node of a large file, say), the first few are printed and the
// rest counted, to be summed up in one line by flushWarnings.
void warn(const std::string& message);
// Prints one line per kind of warning held back since the last call: how many, and the
// last of them. Call it when a step that may warn repeatedly ends (loading a scene).
void flushWarnings();
// Prints "wavepath: note: <message>" on stderr.
void note(const std::string& message);

// Text taken from a file (a name, a library's message) made fit for one message line:
// control characters become spaces, and past maxLength characters it ends in "...".
std::string printable(const std::string& text, size_t maxLength);

}  // namespace wp
