// libFuzzer target: a UMAFall release file (an ADL walking trial) of arbitrary bytes through read_umafall_file. A
// t2imu::Error is a correct answer; a crash, a hang or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_release_file.hpp"
#include "har/datasets/umafall.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)t2imu::read_umafall_file(
            write_fuzz_file("UMAFall_Subject_01_ADL_Walking_1_2017-04-14_23-38-23.csv", data, size));
    } catch (const t2imu::Error&) {}
    return 0;
}
