// libFuzzer target: an IMU dataset's manifest.csv of arbitrary bytes through read_imu_dataset (the manifest
// only: paths, counts, UTF-8 and confinement checks). A t2imu::Error is a correct answer; a crash, a hang or a
// sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "core/error.hpp"
#include "fuzz_release_file.hpp"
#include "imu/imu_dataset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string manifest = write_fuzz_file("manifest.csv", data, size);
    try {
        (void)t2imu::read_imu_dataset(std::filesystem::path(manifest).parent_path().string(), /*load_samples=*/false);
    } catch (const t2imu::Error&) {}
    return 0;
}
