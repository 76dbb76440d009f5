// libFuzzer target: a SisFall release file (D05: stairs, a kept activity) of arbitrary bytes through read_sisfall_file.
// A t2imu::Error is a correct answer; a crash, a hang or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_release_file.hpp"
#include "har/datasets/sisfall.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)t2imu::read_sisfall_file(write_fuzz_file("D05_SA01_R01.txt", data, size));
    } catch (const t2imu::Error&) {}
    return 0;
}
