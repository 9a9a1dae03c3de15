// Reading a whole file that a user named, safely: only regular files, of a bounded size.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace wp {

// Reads all of `file`. Throws wp::Error, one line starting with `label` (how messages name the
// file, e.g. "sky 'x.hdr'"), when it does not exist, is not a regular file (a directory, a
// FIFO or a device would block, never end or have no size), is empty, holds more than
// `maxBytes` (checked before anything is allocated), or cannot be read. `expected` says what
// the user should give instead, e.g. "a .hdr or .exr image".
std::vector<unsigned char> readRegularFile(const std::filesystem::path& file, const std::string& label,
                                           uint64_t maxBytes, const std::string& expected);

}  // namespace wp
