#include "imu/realworld_export.hpp"

#include <cmath>
#include <cstdio>

#include "core/atomic_file.hpp"

namespace t2imu {

namespace {

std::string realworld_file(const ImuSignals& s, bool gyro, long long start_ms) {
    std::string out = "id,attr_time,attr_x,attr_y,attr_z\n";
    char line[160];
    for (size_t k = 0; k < s.t.size(); ++k) {
        const Eigen::Vector3d& v = gyro ? s.gyr[k] : s.acc[k];
        const long long ms = start_ms + std::llround(s.t[k] * 1000.0);
        const int n = std::snprintf(line, sizeof line, "%zu,%lld,%.7f,%.7f,%.7f\n", k + 1, ms, v.x(), v.y(), v.z());
        out.append(line, static_cast<size_t>(n));
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
