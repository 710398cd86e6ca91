// libFuzzer entry point for lacrima::fuzz::loadPerformanceTrackInput (see fuzz_inputs.hpp for the contract).
#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lacrima::fuzz::loadPerformanceTrackInput(data, size);
  return 0;
}
