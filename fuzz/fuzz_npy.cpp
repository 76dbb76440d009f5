// libFuzzer target: parse_npy on arbitrary bytes. A t2imu::Error is a correct answer; a crash or a sanitizer
// report is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "core/npy.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const t2imu::NdArray a = t2imu::parse_npy(data, size, "fuzz.npy");
        (void)a.to<double>();
    } catch (const t2imu::Error&) {}
    return 0;
}
