// Quaternion and 6D helpers against the official common/quaternion.py outputs (shared reference helpers), plus
// identities that hold for any rotation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/npy.hpp"
#include "motion/quaternion.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

std::vector<double> helper(const std::string& name) {
    return read_npy(test::shared_path("reference/humanml3d/generated/helpers/" + name + ".npy")).to<double>();
}
Quat quat_at(const std::vector<double>& v, size_t i) {
    return Quat(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
}
Eigen::Vector3d vec_at(const std::vector<double>& v, size_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }

}  // namespace

TEST(Quaternion, MatchesReferenceHelpers) {
    std::string q_path;
    SHARED_OR_SKIP(q_path, "reference/humanml3d/generated/helpers/q.npy");
    const auto q = helper("q"), r = helper("r"), v = helper("v"), v1 = helper("v1");
    const auto mul = helper("qmul_q_r"), rot = helper("qrot_q_v"), inv = helper("qinv_q"),
               between = helper("qbetween_v_v1");
    const auto mat = helper("quaternion_to_matrix_q"), c6 = helper("quaternion_to_cont6d_q");
    const size_t n = q.size() / 4;
    ASSERT_GT(n, 0u);
    double worst = 0;
    for (size_t i = 0; i < n; ++i) {
        const Quat qi = quat_at(q, i), ri = quat_at(r, i);
        worst = std::max(worst, (qmul(qi, ri).coeffs() - quat_at(mul, i).coeffs()).cwiseAbs().maxCoeff());
        worst = std::max(worst, (qrot(qi, vec_at(v, i)) - vec_at(rot, i)).cwiseAbs().maxCoeff());
        worst = std::max(worst, (qinv(qi).coeffs() - quat_at(inv, i).coeffs()).cwiseAbs().maxCoeff());
        worst = std::max(
            worst,
            (qbetween(vec_at(v, i), vec_at(v1, i)).coeffs() - quat_at(between, i).coeffs()).cwiseAbs().maxCoeff());
        const Eigen::Matrix3d m = quaternion_to_matrix(qi);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) worst = std::max(worst, std::fabs(m(a, b) - mat[9 * i + 3 * a + b]));
        const Cont6d c = quaternion_to_cont6d(qi);
        for (int k = 0; k < 6; ++k) worst = std::max(worst, std::fabs(c[k] - c6[6 * i + k]));
    }
    EXPECT_LT(worst, 1e-5);  // the reference computes in float32
}

TEST(Quaternion, Cont6dToMatrixMatchesReference) {
    std::string in;
    SHARED_OR_SKIP(in, "reference/humanml3d/generated/helpers/cont6d_in.npy");
    const auto c = helper("cont6d_in"), expected = helper("cont6d_to_matrix_cont6d_in");
    double worst = 0;
    for (size_t i = 0; i < c.size() / 6; ++i) {
        Cont6d ci;
        for (int k = 0; k < 6; ++k) ci[k] = c[6 * i + k];
        const Eigen::Matrix3d m = cont6d_to_matrix(ci);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) worst = std::max(worst, std::fabs(m(a, b) - expected[9 * i + 3 * a + b]));
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(Quaternion, QfixMatchesReference) {
    std::string in;
    SHARED_OR_SKIP(in, "reference/humanml3d/generated/helpers/qfix_in.npy");
    const NdArray a = read_npy(in);
    ASSERT_EQ(a.shape.size(), 3u);
    const size_t frames = static_cast<size_t>(a.shape[0]), joints = static_cast<size_t>(a.shape[1]);
    ASSERT_LE(joints, 22u);
    const auto v = a.to<double>(), expected = helper("qfix_out");
    std::vector<std::array<Quat, 22>> seq(frames);
    for (size_t f = 0; f < frames; ++f)
        for (size_t j = 0; j < 22; ++j) seq[f][j] = j < joints ? quat_at(v, f * joints + j) : Quat::Identity();
    qfix(seq);
    double worst = 0;
    for (size_t f = 0; f < frames; ++f)
        for (size_t j = 0; j < joints; ++j)
            worst = std::max(worst,
                             (seq[f][j].coeffs() - quat_at(expected, f * joints + j).coeffs()).cwiseAbs().maxCoeff());
    EXPECT_LT(worst, 1e-12);
}

TEST(Quaternion, SlerpFollowsTheShortArcAtConstantSpeed) {
    const Quat a(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()));
    const Quat b(Eigen::AngleAxisd(1.4, Eigen::Vector3d::UnitY()));
    Quat b_neg = b;
    b_neg.coeffs() *= -1;  // the same rotation: slerp must not take the long way round
    for (double t : {0.0, 0.25, 0.5, 1.0}) {
        const Quat expected(Eigen::AngleAxisd(0.2 + 1.2 * t, Eigen::Vector3d::UnitY()));
        EXPECT_LT(slerp(a, b, t).angularDistance(expected), 1e-12);
        EXPECT_LT(slerp(a, b_neg, t).angularDistance(expected), 1e-12);
    }
}
