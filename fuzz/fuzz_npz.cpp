// libFuzzer target: parse_npz (libzip from memory, then each member's .npy) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "core/npz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)t2imu::parse_npz(data, size, "fuzz.npz");
    } catch (const t2imu::Error&) {}
    return 0;
}
