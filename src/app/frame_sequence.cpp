// Image sequences of `wavepath render --frames A..B --fps F`: the frame range and the output names.
#include "app/frame_sequence.h"

#include <charconv>

#include "core/error.h"

namespace wp {

namespace {

bool parseFrame(const std::string& text, uint32_t& out) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return !text.empty() && ec == std::errc() && ptr == end;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, const std::string& example) {
  auto badRange = [&](const std::string& why) {
    throw Error("'" + text + "': " + why + "; give a range such as " + example);
  };
  const size_t dots = text.find("..");
  FrameRange range;
  const std::string first = text.substr(0, dots);
  if (!parseFrame(first, range.first)) badRange("'" + first + "' is not a whole number (0 or more)");
  range.last = range.first;
  if (dots == std::string::npos) return range;
  const std::string last = text.substr(dots + 2);
  if (!parseFrame(last, range.last)) badRange("'" + last + "' is not a whole number (0 or more)");
  if (range.first > range.last) badRange("the first comes after the last");
  return range;
}

std::string framePath(const std::string& pattern, uint32_t frame) {
  const size_t end = pattern.find_last_of('#');
  if (end == std::string::npos) return pattern;
  size_t begin = end;
  while (begin > 0 && pattern[begin - 1] == '#') --begin;
  std::string number = std::to_string(frame);
  const size_t width = end + 1 - begin;
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return pattern.substr(0, begin) + number + pattern.substr(end + 1);
}

void checkFramePattern(const std::string& pattern, const FrameRange& range) {
  if (range.first != range.last && pattern.find('#') == std::string::npos) {
    throw Error("-o '" + pattern + "' has no '#' for the frame number, so every frame of --frames would overwrite " +
                "the last; name the output like out_####.png");
  }
}

}  // namespace wp
