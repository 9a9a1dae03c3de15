// Independent jobs spread over the machine's cores.
#pragma once

#include <cstdint>
#include <functional>

namespace wp {

// Calls work(i) for every i in [0, count), on as many threads as the machine has cores (the
// calling thread among them, and never more threads than jobs), each thread taking the next
// index as it finishes one. After every thread has stopped, rethrows the first exception a
// call threw; the calls not yet started when it was thrown are skipped.
void forEachInParallel(uint32_t count, const std::function<void(uint32_t)>& work);

}  // namespace wp
