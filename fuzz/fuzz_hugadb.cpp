// libFuzzer target: a HuGaDB release file of arbitrary bytes through read_hugadb_file. A t2imu::Error is a
// correct answer; a crash, a hang or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_release_file.hpp"
#include "har/datasets/hugadb.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)t2imu::read_hugadb_file(write_fuzz_file("HuGaDB_v1_walking_01_00.txt", data, size));
    } catch (const t2imu::Error&) {}
    return 0;
}
