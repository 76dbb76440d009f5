// libFuzzer target: the CSV writers' numbers. The input's bytes are read as doubles (any bit pattern: huge, tiny,
// denormal, NaN, infinite), each through the number text helpers (core/number_text) and, as the samples of one
// recording, through write_imu_recording and back through read_imu_dataset. A t2imu::Error naming a refused value
// is a correct answer; anything else that differs is a bug, reported by abort():
//  - a number's text holds only its digits, sign, point (and exponent, or nan/inf) and reads back to the value
//    within half its last decimal;
//  - a recording the writer accepts reads back sample for sample within 5e-7 (6 decimals), and one it refuses
//    held a value the writer's range excludes (non-finite, beyond ±1e6), with nothing written.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "fuzz_release_file.hpp"
#include "imu/imu_dataset.hpp"

namespace {

void check_number(double v, int decimals) {
    const std::string fixed = t2imu::fixed_text(v, decimals), general = t2imu::general_text(v, decimals + 1);
    if (fixed.size() > 330 || general.size() > 32) std::abort();
    if (!std::isfinite(v)) return;
    if (fixed.find_first_not_of("-0123456789.") != std::string::npos) std::abort();
    const double back = std::strtod(fixed.c_str(), nullptr);
    // Half the last decimal, plus the double's own spacing at v (fixed notation of 1e300 is exact to the digit).
    if (std::fabs(back - v) > 0.5 * std::pow(10.0, -decimals) + std::fabs(v) * 1e-15) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<double> values(size / 8);
    for (size_t i = 0; i < values.size(); ++i) std::memcpy(&values[i], data + 8 * i, 8);
    for (size_t i = 0; i < values.size(); ++i) check_number(values[i], static_cast<int>(data[8 * i] % 18));
    const size_t n = values.size() / 6;
    if (n == 0) return 0;
    t2imu::ImuSignals s;
    s.rate_hz = 50;
    bool in_range = true;
    for (size_t k = 0; k < n; ++k) {
        const double* six = &values[6 * k];
        s.t.push_back(static_cast<double>(k) / s.rate_hz);
        s.acc.emplace_back(six[0], six[1], six[2]);
        s.gyr.emplace_back(six[3], six[4], six[5]);
        for (int c = 0; c < 6; ++c) in_range = in_range && std::isfinite(six[c]) && std::fabs(six[c]) <= 1e6;
    }
    const std::string csv = write_fuzz_file("r.csv", nullptr, 0);
    std::filesystem::remove(csv);
    try {
        t2imu::write_imu_recording(csv, s);
    } catch (const t2imu::Error&) {
        if (in_range || std::filesystem::exists(csv))
            std::abort();  // refused only what its range excludes, writing nothing
        return 0;
    }
    if (!in_range) std::abort();
    t2imu::ImuRecording row;
    row.path = "r.csv";
    row.rate_hz = s.rate_hz;
    row.n_samples = n;
    const std::string dir = std::filesystem::path(csv).parent_path().string();
    t2imu::write_imu_manifest(dir, {row});
    const std::vector<t2imu::ImuRecording> back = t2imu::read_imu_dataset(dir);  // an Error here is a bug: let it crash
    if (back.size() != 1 || back[0].samples.size() != n) std::abort();
    for (size_t k = 0; k < n; ++k)
        for (int c = 0; c < 6; ++c)
            if (std::fabs(back[0].samples[k][c] - values[6 * k + c]) > 5e-7 + 1e-12 * std::fabs(values[6 * k + c]))
                std::abort();
    return 0;
}
