// One-line messages for glTF errors and warnings.
#include "scene/gltf_context.h"

#include "core/error.h"
#include "core/log.h"

namespace wp::gltf {

namespace {

constexpr size_t kMaxNameLength = 60;
constexpr size_t kMaxPartLength = 200;

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// tinygltf quotes a bad buffer's whole data: URI; its payload says nothing to a user.
std::string withoutDataPayload(std::string text) {
  const size_t data = text.find("data:");
  const size_t comma = data == std::string::npos ? data : text.find(',', data);
  if (comma == std::string::npos) return text;
  const size_t end = text.find_first_of(" \t'\"", comma);
  return text.replace(comma + 1, (end == std::string::npos ? text.size() : end) - comma - 1, "...");
}

std::string join(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  return b.empty() ? a : a + ": " + b;
}

}  // namespace

std::string describe(const char* kind, size_t index, const std::string& name) {
  std::string out = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) out += " '" + printable(name, kMaxNameLength) + "'";
  return out;
}

void fail(const Context& ctx, const std::string& where, const std::string& message) {
  throw Error(join(ctx.file, join(where, message)));
}

void warnAt(const Context& ctx, const std::string& where, const std::string& message) {
  warn(join(ctx.file, join(where, message)));
}

std::string oneLine(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string part = withoutDataPayload(trim(text.substr(start, end - start)));
    while (!part.empty() && part.back() == '.') part.pop_back();  // the caller punctuates
    if (!part.empty()) out += (out.empty() ? "" : "; ") + printable(part, kMaxPartLength);
    start = end + 1;
  }
  return out;
}

std::string missingIndex(long long index, size_t count, const char* plural) {
  std::string noun = plural;
  if (count == 1) noun.pop_back();
  return std::to_string(index) + " does not exist (the file has " + std::to_string(count) + " " +
         noun + ")";
}

}  // namespace wp::gltf
