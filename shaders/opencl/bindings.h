// The arguments every OpenCL stage kernel takes, generated from the binding table
// (common/binding_table.h): the OpenCL counterpart of ../vulkan/bindings.glsl.
#ifndef WP_OPENCL_BINDINGS_H
#define WP_OPENCL_BINDINGS_H

#include "common/binding_table.h"

// Kernel argument i is the buffer of binding i for every row of the table for ALL backends
// (so the host sets each buffer once for all kernels); the pass constants follow, by value.
// The parameters come as a constant pointer, paramsBuffer.
#define WP_CL_ARGUMENT(name, binding, Element, stride, format, access, backends) \
  WP_ON_OPENCL_##backends(WP_CL_ARGUMENT_##access(name, Element))
#define WP_CL_ARGUMENT_UNIFORM(name, Element) __constant Element *name##Buffer,
#define WP_CL_ARGUMENT_TEXELS(name, Element) __global const Element *name,
#define WP_CL_ARGUMENT_STORAGE(name, Element) __global Element *name,
#define WP_CL_ARGUMENT_WRITE(name, Element) __global Element *name,
#define WP_CL_ARGUMENT_TEXEL_VIEW(name, Element)
#define WP_CL_ARGUMENT_CONSTANT(name, Element)
#define WP_KERNEL_ARGS WP_BINDINGS(WP_CL_ARGUMENT) PassConstants pc

// Declares `buffers`, the kernel's buffer arguments as the DeviceBuffers bundle the stage
// functions take, in local memory: work item 0 fills it once for the work-group. PoCL does
// not inline the large functions, so the bundle lives in memory; a private one would be
// written by every work item (2% more instructions per path, counted with callgrind).
#define WP_KERNEL_BUFFERS(buffers)                                     \
  __local DeviceBuffers buffers;                                       \
  if (get_local_id(0) == 0u) {                                         \
    DeviceBuffers arguments = {WP_BINDINGS(WP_CL_BUNDLE_MEMBER)};     \
    buffers = arguments;                                               \
  }                                                                    \
  barrier(CLK_LOCAL_MEM_FENCE);
#define WP_CL_BUNDLE_MEMBER(name, binding, Element, stride, format, access, backends) \
  WP_ON_OPENCL_##backends(WP_CL_BUNDLE_MEMBER_##access(name))
#define WP_CL_BUNDLE_MEMBER_UNIFORM(name)
#define WP_CL_BUNDLE_MEMBER_TEXELS(name) name,
#define WP_CL_BUNDLE_MEMBER_STORAGE(name) name,
#define WP_CL_BUNDLE_MEMBER_WRITE(name) name,
#define WP_CL_BUNDLE_MEMBER_TEXEL_VIEW(name)
#define WP_CL_BUNDLE_MEMBER_CONSTANT(name)

// Every dispatch runs workgroups of WP_WORKGROUP_SIZE, which lets the compiler specialise.
#define WP_KERNEL __kernel __attribute__((reqd_work_group_size(WP_WORKGROUP_SIZE, 1, 1)))

#endif
