// The program holding every stage kernel, built for one device through the binary cache.
#pragma once

#include <CL/cl.h>

#include <string>
#include <vector>

#include "backend/opencl/opencl_context.h"
#include "backend/opencl/program_cache.h"

namespace wp {

class OpenClProgram {
public:
  // Builds the embedded kernels (opencl/opencl_source.h) with `options`: from the cached
  // binary when one matches device, driver, options and source, else from source (saying
  // so in a note). WAVEPATH_CL_EXTRA_SOURCE, when set, is appended to the source: a hook
  // for testing the build-failure path. On a compile error the compiler's log goes to
  // stderr and a wp::Error follows.
  OpenClProgram(const OpenClContext& context, const std::string& options);
  ~OpenClProgram();
  OpenClProgram(const OpenClProgram&) = delete;
  OpenClProgram& operator=(const OpenClProgram&) = delete;

  cl_program handle() const { return program_; }

  // Stores the binary in the cache if this run compiled it; later calls do nothing. Call it
  // once the kernels have run: drivers that compile lazily (PoCL compiles a kernel's
  // work-group function at its first launch) put that code into the binary only then.
  void cacheBinary();

private:
  // Builds from the cached binary; false (and no program) when that does not work.
  bool buildFromBinary(const OpenClContext& context, const std::vector<unsigned char>& binary,
                       const std::string& options);
  void buildFromSource(const OpenClContext& context, const std::string& source, const std::string& options);

  cl_program program_ = nullptr;
  ProgramCache cache_;
  bool compiled_ = false;  // built from source and not cached yet
};

}  // namespace wp
