// libFuzzer target: see fuzz_harness.hpp.
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return fuzz::recordings_one(data, size); }
