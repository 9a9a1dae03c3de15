// The device a backend takes without --device, one rule for every backend's device list.
#pragma once

#include <vector>

namespace wp {

// The index of the best-ranked device of `devices` (each with an int `rank`, higher
// preferred) for which `usable(device)` holds, the first of equal ranks; -1 when none is.
template <typename Device, typename Usable>
int mostCapableUsable(const std::vector<Device>& devices, Usable usable) {
  int best = -1;
  for (size_t i = 0; i < devices.size(); ++i) {
    if (usable(devices[i]) && (best < 0 || devices[i].rank > devices[best].rank)) best = int(i);
  }
  return best;
}

}  // namespace wp
