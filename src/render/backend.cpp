// Names of the wavefront kernels, for timings and messages.
#include "render/backend.h"

namespace wp {

const char* kernelName(Kernel kernel) {
  switch (kernel) {
    case Kernel::Generate: return "generate";
    case Kernel::Extend: return "extend";
    case Kernel::Shade: return "shade";
    case Kernel::Advance: return "advance";
    case Kernel::Connect: return "connect";
    case Kernel::Accumulate: return "accumulate";
  }
  return "?";
}

}  // namespace wp
