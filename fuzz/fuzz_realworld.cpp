// libFuzzer target: a RealWorld sensor archive of arbitrary bytes (proband1/data/acc_walking_csv.zip: the zip
// reader, nested part archives, the CSV columns, the 50 Hz grid) through read_realworld_proband. A t2imu::Error
// or a skipped archive is a correct answer; a crash, a hang or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_release_file.hpp"
#include "har/datasets/realworld.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const bool folders = [] {
        std::filesystem::create_directories(std::filesystem::path(write_fuzz_file("probe", nullptr, 0)).parent_path() /
                                            "proband1/data");
        return true;
    }();
    (void)folders;
    const std::string archive = write_fuzz_file("proband1/data/acc_walking_csv.zip", data, size);
    try {
        std::vector<std::string> skipped;
        (void)t2imu::read_realworld_proband(std::filesystem::path(archive).parent_path().parent_path().string(),
                                            &skipped);
    } catch (const t2imu::Error&) {}
    return 0;
}
