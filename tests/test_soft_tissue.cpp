// The attachment's spring-mass (imu/soft_tissue): rest, a constant push, and an impulse response whose
// frequency and decay are the ones set.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "imu/realism.hpp"
#include "imu/soft_tissue.hpp"

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
