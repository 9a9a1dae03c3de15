// Image sequences of `wavepath render --frames A..B --fps F`: the frame range and the output names.
#pragma once

#include <cstdint>
#include <string>

namespace wp {

struct FrameRange {
  uint32_t first = 0;
  uint32_t last = 0;  // inclusive
};

// Parses "A..B" (whole numbers, A <= B) or a single number "A" (frames, or samples of
// --samples). Throws a one-line wp::Error quoting the text and ending with `example` on
// anything else (the caller names the flag).
FrameRange parseFrameRange(const std::string& text, const std::string& example = "--frames 0..47");

// `pattern` with its last run of '#' replaced by `frame`, zero-padded to the run's length
// (longer numbers are written in full): "out_####.png", 7 -> "out_0007.png". Without a
// '#' the pattern is returned as is.
std::string framePath(const std::string& pattern, uint32_t frame);

// Throws a one-line wp::Error when a sequence of several frames would write every frame to
// the same file, because `pattern` has no '#'.
void checkFramePattern(const std::string& pattern, const FrameRange& range);

}  // namespace wp
