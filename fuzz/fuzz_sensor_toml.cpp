// libFuzzer target: a custom sensor set (imu/placement.hpp's TOML) read from arbitrary bytes. A t2imu::Error
// is a correct answer; a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "imu/placement.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)t2imu::parse_placement_toml(std::string(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    } catch (const t2imu::Error&) {}
    return 0;
}
