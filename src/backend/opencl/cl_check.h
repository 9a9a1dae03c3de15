// CL_CHECK: turns a failed OpenCL call into a wp::Error naming the call, file:line, the
// error and what to do.
#pragma once

#include <CL/cl.h>

namespace wp::cl {

const char* errorName(cl_int error);
// Throws wp::Error when error is not CL_SUCCESS.
void check(cl_int error, const char* call, const char* file, int line);

}  // namespace wp::cl

#define CL_CHECK(call) ::wp::cl::check((call), #call, __FILE__, __LINE__)
