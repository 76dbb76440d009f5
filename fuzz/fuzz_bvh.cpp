// libFuzzer target: parse_bvh, then the pose and forward kinematics of every frame, on arbitrary text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "motion/bvh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const t2imu::BvhMotion m = t2imu::parse_bvh(std::string(reinterpret_cast<const char*>(data), size), "fuzz.bvh");
        for (int f = 0; f < m.num_frames && f < 64; ++f) (void)t2imu::bvh_forward_kinematics(m, t2imu::bvh_pose(m, f));
        (void)t2imu::format_bvh(m);
    } catch (const t2imu::Error&) {}
    return 0;
}
