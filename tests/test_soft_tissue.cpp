// The attachment's spring-mass (imu/soft_tissue): rest, a constant push, an impulse response whose frequency and
// decay are the ones set, and the RK4 stability bound the realism table enforces.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "imu/realism.hpp"
#include "imu/soft_tissue.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

TEST(SoftTissue, BaseAtRestLeavesTheMassAtRest) {
    const std::vector<Vector3d> base(2000, Vector3d::Zero());
    const SpringMassResponse r = spring_mass_response(base, 1e-3, {10, 0.3});
    for (size_t i = 0; i < base.size(); ++i) {
        EXPECT_EQ(r.displacement[i].norm(), 0);
        EXPECT_EQ(r.acceleration[i].norm(), 0);
    }
}

TEST(SoftTissue, ConstantBaseAccelerationSettlesAtTheStaticDeflection) {
    // u'' + 2 zeta w u' + w^2 u = -b  ->  u = -b / w^2 once the transient is gone; the mass then moves with the base.
    const Vector3d b(0, 3.0, -1.0);
    const std::vector<Vector3d> base(3000, b);
    const SoftTissue tissue{10, 0.5};
    const SpringMassResponse r = spring_mass_response(base, 1e-3, tissue);
    const double w = 2 * M_PI * 10;
    EXPECT_NEAR((r.displacement.back() + b / (w * w)).norm(), 0, 1e-9);
    EXPECT_NEAR(r.acceleration.back().norm(), 0, 1e-6);
}

TEST(SoftTissue, ImpulseResponseRingsAtTheDampedFrequencyAndDecaysAsSet) {
    const double fn = 12, zeta = 0.1, dt = 1e-4;
    std::vector<Vector3d> base(20000, Vector3d::Zero());
    base[1] = Vector3d(0, 1.0 / dt, 0);  // an impulse: unit velocity change of the base
    const SpringMassResponse r = spring_mass_response(base, dt, {fn, zeta});
    // Upward zero crossings of u give the damped period; successive peaks of u give the logarithmic decrement.
    std::vector<double> crossings, peaks;
    for (size_t i = 3; i + 1 < base.size(); ++i) {
        const double a = r.displacement[i - 1].y(), b = r.displacement[i].y(), c = r.displacement[i + 1].y();
        if (a < 0 && b >= 0) crossings.push_back((static_cast<double>(i) - 1 + a / (a - b)) * dt);
        if (b < a && b <= c) peaks.push_back(-b);  // troughs: u swings to -1/w_d first
    }
    ASSERT_GE(crossings.size(), 5u);
    ASSERT_GE(peaks.size(), 5u);
    const double period = (crossings[4] - crossings[0]) / 4;
    EXPECT_NEAR(1 / period, fn * std::sqrt(1 - zeta * zeta), 0.01);
    const double delta = std::log(peaks[0] / peaks[1]);  // = 2 pi zeta / sqrt(1 - zeta^2)
    EXPECT_NEAR(delta / std::sqrt(4 * M_PI * M_PI + delta * delta), zeta, 1e-3);
    // u = -e^{-zeta w t} sin(w_d t) / w_d; its first trough is at w_d t = pi/2 - atan(zeta / sqrt(1 - zeta^2)).
    const double wd = 2 * M_PI * fn * std::sqrt(1 - zeta * zeta);
    const double t = (M_PI / 2 - std::atan(zeta / std::sqrt(1 - zeta * zeta))) / wd;
    EXPECT_NEAR(peaks[0], std::exp(-zeta * 2 * M_PI * fn * t) * std::sqrt(1 - zeta * zeta) / wd, 2e-5);
}

TEST(SoftTissue, RigidAttachmentIsNoFilterAndBadValuesAreRefused) {
    const std::vector<Vector3d> base = {Vector3d(1, 2, 3), Vector3d(-4, 5, 6)};
    const SpringMassResponse r = spring_mass_response(base, 1e-3, {});
    EXPECT_EQ(r.acceleration[1].norm(), 0);
    // Ranges live in the realism table (imu/realism.cpp).
    EXPECT_THROW(parse_realism_toml("tissue_hz = 0.5\ntissue_damping = 0.3\n", "t.toml"), Error);
    EXPECT_THROW(parse_realism_toml("tissue_hz = 10\n", "t.toml"), Error);  // no damping
    EXPECT_NO_THROW(parse_realism_toml("tissue_hz = 0\n", "t.toml"));
}

TEST(SoftTissue, RungeKuttaGrowthMatchesItsStabilityLimitAndUnstableSettingsAreRefused) {
    // RK4 on the real axis is stable down to z = -2.785293563 (the real root of z^3 + 4 z^2 + 12 z + 24 = 0).
    const double limit = 2.785293563, dt = 1 / kAttachmentRateHz;
    const double zeta = 2, fast = zeta + std::sqrt(zeta * zeta - 1);  // the fast root, omega (zeta + sqrt(zeta^2 - 1))
    const double f_limit = limit / (2 * M_PI * fast * dt);            // 118.8 Hz at zeta = 2
    EXPECT_LE(rk4_growth_per_step({f_limit * 0.999, zeta}, dt), 1.0);
    EXPECT_GT(rk4_growth_per_step({f_limit * 1.001, zeta}, dt), 1.0);
    EXPECT_LT(rk4_growth_per_step({200, 0.5}, dt),
              1.0);  // underdamped at the top of the range: |z| = 1.26, well inside
    EXPECT_EQ(rk4_growth_per_step({}, dt), 0.0);
    // What the growth means: the documented tissue_hz = 150 with tissue_damping = 2 rings without bound.
    std::vector<Vector3d> step(2000, Vector3d(0, 9.81, 0));
    const Vector3d last = spring_mass_response(step, dt, {150, 2}).acceleration.back();
    EXPECT_TRUE(!last.allFinite() || last.norm() > 1e6) << last.transpose();
    EXPECT_LT(spring_mass_response(step, dt, {118, 2}).acceleration.back().norm(), 1e-6);  // just stable: settles
    // The realism table refuses the unstable pairs, naming both keys; the stable side of the bound is accepted.
    for (const char* toml : {"tissue_hz = 150\ntissue_damping = 2\n", "tissue_hz = 200\ntissue_damping = 1.5\n",
                             "strap_hz = 150\nstrap_damping = 2\n"}) {
        const std::string m = test::error_message([&] { parse_realism_toml(toml, "r.toml"); });
        EXPECT_TRUE(test::contains(m, "r.toml") && test::contains(m, "_hz with ") && test::contains(m, "_damping") &&
                    test::contains(m, "stable"))
            << m;
    }
    EXPECT_NO_THROW(parse_realism_toml("tissue_hz = 200\ntissue_damping = 1.3\n", "r.toml"));
    EXPECT_NO_THROW(parse_realism_toml("strap_hz = 118\nstrap_damping = 2\n", "r.toml"));
}
