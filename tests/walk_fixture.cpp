#include "walk_fixture.hpp"

#include <cmath>

#include "motion/motion_edit.hpp"
#include "motion/two_bone_ik.hpp"
#include "test_util.hpp"

namespace t2imu::test {

JointSequence procedural_walk(double seconds, double fps) {
    using Eigen::Vector3d;
    using namespace smpl22;
    const int n = static_cast<int>(seconds * fps) + 1;
    JointSequence m(n, kNumJoints, fps);
    for (int f = 0; f < n; ++f) {
        const double t = f / fps;
        m.at(f, pelvis) = Vector3d(0, kWalkPelvisHeight, t);
        for (int j = 1; j < kNumJoints; ++j)
            if (!is_leg_joint(j))
                m.at(f, j) = m.at(f, kParents[static_cast<size_t>(j)]) + kTargetOffsets[static_cast<size_t>(j)];
        for (int side = 0; side < 2; ++side) {
            const LegJoints& leg = kLegs[static_cast<size_t>(side)];
            const double cycle = t + 0.5 * side, phase = cycle - std::floor(cycle);
            // Stance of cycle c: the pelvis passes over the foot at its middle, 0.3 s after landing.
            double z = std::floor(cycle) - 0.5 * side + 0.3, lift = 0;
            if (phase >= 0.6) {
                const double s = (phase - 0.6) / 0.4;
                z += min_jerk(s);
                lift = 0.06 * std::sin(kPi * s);
            }
            m.at(f, leg.ankle) = Vector3d(m.at(f, leg.hip).x(), kAnkleHeight + lift, z);
            const double foot = kTargetOffsets[static_cast<size_t>(leg.toe)].norm(), drop = kAnkleHeight - kToeHeight;
            m.at(f, leg.toe) = m.at(f, leg.ankle) + Vector3d(0, -drop, std::sqrt(foot * foot - drop * drop));
            m.at(f, leg.knee) = solve_two_bone_ik(m.at(f, leg.hip), m.at(f, leg.ankle),
                                                  kTargetOffsets[static_cast<size_t>(leg.knee)].norm(),
                                                  kTargetOffsets[static_cast<size_t>(leg.ankle)].norm(),
                                                  m.at(f, leg.hip) + Vector3d(0, -0.4, 1))
                                    .middle;
        }
    }
    return m;
}

}  // namespace t2imu::test
