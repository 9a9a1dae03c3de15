// Files that appear whole or not at all: written beside their place, flushed, renamed.
#pragma once

#include <filesystem>
#include <vector>

namespace wp {

// Writes `bytes` to a uniquely named hidden file beside `path`, flushes it to disk and
// renames it over `path`: rename is atomic within a directory, so readers (and a crash) see
// either the old file or the complete new one. Throws wp::Error "cannot write <what>
// '<path>': ..." on failure, leaving no temporary file behind. A termination signal
// (SIGINT, SIGTERM, SIGHUP, SIGQUIT) that comes meanwhile takes effect once the temporary
// file is renamed or removed.
void writeFileAtomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes,
                         const char* what);

}  // namespace wp
