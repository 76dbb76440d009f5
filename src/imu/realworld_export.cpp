#include "imu/realworld_export.hpp"

#include <cmath>

#include "core/atomic_file.hpp"
#include "core/number_text.hpp"

namespace t2imu {

namespace {

// The samples were checked when the recording's CSV was written (imu_dataset.hpp); the milliseconds are whole.
std::string realworld_file(const ImuSignals& s, bool gyro, long long start_ms) {
    std::string out = "id,attr_time,attr_x,attr_y,attr_z\n";
    for (size_t k = 0; k < s.t.size(); ++k) {
        const Eigen::Vector3d& v = gyro ? s.gyr[k] : s.acc[k];
        out += std::to_string(k + 1) + "," + std::to_string(start_ms + std::llround(s.t[k] * 1000.0));
        for (int i = 0; i < 3; ++i) {
            out += ',';
            append_fixed(out, v[i], 7);
        }
        out += '\n';
    }
    return out;
}

}  // namespace

void write_realworld_csv(const std::string& dir, const std::string& activity, const std::string& position,
                         const ImuSignals& s, long long start_ms) {
    write_file_atomic(dir + "/acc_" + activity + "_" + position + ".csv", realworld_file(s, false, start_ms));
    write_file_atomic(dir + "/Gyroscope_" + activity + "_" + position + ".csv", realworld_file(s, true, start_ms));
}

}  // namespace t2imu
