#include "imu/imu_writer.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/atomic_file.hpp"

namespace t2imu {

namespace {

void append_row(std::string& out, const char* fmt, double a, double b, double c, double d, double e, double f, double g) {
    char line[256];
    const int n = std::snprintf(line, sizeof line, fmt, a, b, c, d, e, f, g);
    out.append(line, static_cast<size_t>(n));
}

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

void write_imu_csv(const std::string& path, const ImuSignals& s) {
    std::string out = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
    out.reserve(out.size() + s.t.size() * 80);
    for (size_t k = 0; k < s.t.size(); ++k)
        append_row(out, "%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", s.t[k], s.acc[k].x(), s.acc[k].y(), s.acc[k].z(),
                   s.gyr[k].x(), s.gyr[k].y(), s.gyr[k].z());
    write_file_atomic(path, out);
}

void write_realworld_csv(const std::string& dir, const std::string& activity, const std::string& position,
                         const ImuSignals& s, long long start_ms) {
    write_file_atomic(dir + "/acc_" + activity + "_" + position + ".csv", realworld_file(s, false, start_ms));
    write_file_atomic(dir + "/Gyroscope_" + activity + "_" + position + ".csv", realworld_file(s, true, start_ms));
}

}  // namespace t2imu
