// Selects the language prelude so the physics headers compile as GLSL, OpenCL C and C++.
#ifndef WP_PORTABLE_H
#define WP_PORTABLE_H

// Rules for code under shaders/common (so all three compilers accept it):
// - types: float, uint, int, bool, vec2/3/4, uvec2/4; build vectors with make_vec3(...) etc.
// - conversions with toFloat/toUint/toInt, bit casts with asFloat/asUint;
// - float literals carry an f suffix (OpenCL would otherwise compute in double);
// - use fabs for floats (abs is integer-only in OpenCL);
// - no out/inout parameters: functions return structs;
// - structs are declared with WP_STRUCT(Name) ... WP_STRUCT_END(Name);
// - functions are declared WP_FN; code sits between WP_BEGIN and WP_END;
// - no file-scope const variables (OpenCL wants __constant): use #define; a table of
//   constants is WP_FLOAT_TABLE in C++ and OpenCL and a buffer in GLSL (energy_compensation.h);
// - buffers are read with WP_LOAD(name, i) and written through WP_BUFFER(name); a function
//   that touches them takes WP_BUFFERS first and is called with WP_BUFFERS_ARG
//   (binding_table.h).
// WP_BUFFERS_AS_ARGUMENTS: C++ and OpenCL pass buffers to functions as pointers; GLSL reads
// them as globals that the including stage declares. (OpenCL compilers define
// __OPENCL_VERSION__; plain clang -x cl defines only __OPENCL_C_VERSION__.)
#if defined(__cplusplus)
#include "prelude_cpp.h"
#define WP_BUFFERS_AS_ARGUMENTS 1
#elif defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
#include "prelude_cl.h"
#define WP_BUFFERS_AS_ARGUMENTS 1
#else
#include "prelude_glsl.h"
#endif

// A record: a struct whose fields are listed once as F(type, name) entries in
// WP_FIELDS_<Name>, so that code can be generated per field (the GLSL texel loaders).
#define WP_DECLARE_FIELD(type, name) type name;
#define WP_RECORD(Name) WP_STRUCT(Name) WP_FIELDS_##Name(WP_DECLARE_FIELD) WP_STRUCT_END(Name)

#define WP_PI 3.14159265358979f
#define WP_INV_PI 0.318309886183791f
#define WP_FLT_MAX 3.402823466e+38f

#endif
