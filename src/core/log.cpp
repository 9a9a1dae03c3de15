// Warnings and notes on stderr, repeated warnings folded into one line with a count.
#include "core/log.h"

#include <cctype>
#include <cstdio>
#include <map>
#include <mutex>

namespace wp {
namespace {

// Warnings of one kind printed in full before the rest are counted.
constexpr size_t kShownPerKind = 3;

struct Kind {
  size_t count = 0;
  std::string last;  // the latest of those held back
};

std::mutex gMutex;
std::map<std::string, Kind> gKinds;

// The message with every run of digits and every '...' quoted name replaced, so that
// "node 7 'a': ..." and "node 8 'b': ..." are the same kind.
std::string kindOf(const std::string& message) {
  std::string kind;
  bool quoted = false;
  for (size_t i = 0; i < message.size(); ++i) {
    const char c = message[i];
    if (c == '\'') {
      quoted = !quoted;
      if (quoted) kind += "'*'";
    } else if (!quoted && std::isdigit(static_cast<unsigned char>(c))) {
      if (kind.empty() || kind.back() != '#') kind += '#';
    } else if (!quoted) {
      kind += c;
    }
  }
  return kind;
}

}  // namespace

void warn(const std::string& message) {
  const std::lock_guard<std::mutex> lock(gMutex);
  Kind& kind = gKinds[kindOf(message)];
  if (++kind.count <= kShownPerKind) {
    std::fprintf(stderr, "wavepath: warning: %s\n", message.c_str());
  } else {
    kind.last = message;
  }
}

void flushWarnings() {
  const std::lock_guard<std::mutex> lock(gMutex);
  for (const auto& [key, kind] : gKinds) {
    if (kind.count > kShownPerKind) {
      std::fprintf(stderr, "wavepath: warning: %zu more like that, the last: %s\n", kind.count - kShownPerKind,
                   kind.last.c_str());
    }
  }
  gKinds.clear();
}

void note(const std::string& message) { std::fprintf(stderr, "wavepath: note: %s\n", message.c_str()); }

std::string printable(const std::string& text, size_t maxLength) {
  std::string out;
  for (char c : text) {
    if (out.size() >= maxLength) {
      out += "...";
      break;
    }
    out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c;
  }
  return out;
}

}  // namespace wp
