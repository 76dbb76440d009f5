#include "pose_fixture.hpp"

#include "motion/skeleton.hpp"

namespace t2imu::test {

std::array<Eigen::Vector3d, 22> standing_pose() {
    namespace j = smpl22;
    std::array<Eigen::Vector3d, 22> p;
    p[j::pelvis] = {0, 0.9, 0};
    p[j::spine1] = {0, 1.0, 0};
    p[j::spine2] = {0, 1.15, 0};
    p[j::spine3] = {0, 1.25, 0};
    p[j::neck] = {0, 1.4, 0};
    p[j::head] = {0, 1.55, 0};
    for (int side : {-1, 1}) {
        const bool left = side > 0;  // the body's left is +X
        p[left ? j::left_hip : j::right_hip] = {0.1 * side, 0.85, 0};
        p[left ? j::left_knee : j::right_knee] = {0.1 * side, 0.45, 0};
        p[left ? j::left_ankle : j::right_ankle] = {0.1 * side, 0.05, 0};
        p[left ? j::left_foot : j::right_foot] = {0.1 * side, 0.0, 0.1};
        p[left ? j::left_collar : j::right_collar] = {0.05 * side, 1.35, 0};
        p[left ? j::left_shoulder : j::right_shoulder] = {0.18 * side, 1.35, 0};
        p[left ? j::left_elbow : j::right_elbow] = {0.2 * side, 1.1, 0};
        p[left ? j::left_wrist : j::right_wrist] = {0.2 * side, 0.85, 0};
    }
    return p;
}

}  // namespace t2imu::test
