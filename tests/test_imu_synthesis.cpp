// Virtual IMU physics with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "imu/imu_synthesis.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {

constexpr double kSynthesisFps = 20.0;

struct Motion {
    std::vector<Vector3d> p;
    std::vector<Quat> q;
};

template <class Pose>
Motion sample(double seconds, Pose pose) {
    Motion m;
    for (int f = 0; f <= static_cast<int>(seconds * kSynthesisFps); ++f) {
        Vector3d p;
        Quat q;
        pose(f / kSynthesisFps, p, q);
        m.p.push_back(p);
        m.q.push_back(q);
    }
    return m;
}

}  // namespace

TEST(ImuSynthesis, StaticSensorReadsGravityOnItsUpAxis) {
    // Rotated 90 degrees about Z: the sensor's +X axis is mapped onto world +Y, so it points up.
    const Quat tilt(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitZ()));
    const Motion m = sample(2.0, [&](double, Vector3d& p, Quat& q) {
        p = {0.3, 1.1, -0.2};
        q = tilt;
    });
    const ImuSignals s = synthesize_imu(m.p, m.q, kSynthesisFps, 50);
    EXPECT_EQ(s.t.size(), 101u);
    for (size_t k = 0; k < s.t.size(); ++k) {
        EXPECT_NEAR(s.acc[k].norm(), kGravity, 1e-9);
        EXPECT_NEAR(s.acc[k].x(), kGravity, 1e-9);  // sensor +X is world +Y (up)
        EXPECT_LT(s.gyr[k].norm(), 1e-9);
    }
}

TEST(ImuSynthesis, ConstantVelocityGivesGravityOnly) {
    const Motion m = sample(3.0, [](double t, Vector3d& p, Quat& q) {
        p = Vector3d(1.4 * t, 0.9, -0.3 * t);
        q = Quat::Identity();
    });
    const ImuSignals s = synthesize_imu(m.p, m.q, kSynthesisFps, 100);
    for (const Vector3d& a : s.acc) EXPECT_LT((a - Vector3d(0, kGravity, 0)).norm(), 1e-9);
}

TEST(ImuSynthesis, TurningInPlaceGivesYawRateAndCentripetalForce) {
    // A body turns about the world Y axis at w = 1.5 rad/s; a sensor 0.2 m from the axis turns with it.
    const double w = 1.5, r = 0.2;
    const Motion m = sample(4.0, [&](double t, Vector3d& p, Quat& q) {
        q = Quat(Eigen::AngleAxisd(w * t, Vector3d::UnitY()));
        p = q * Vector3d(r, 1.0, 0);
    });
    const ImuSignals s = synthesize_imu(m.p, m.q, kSynthesisFps, 50);
    double worst_gyr = 0, worst_acc = 0;
    for (size_t k = 0; k < s.t.size(); ++k) {
        worst_gyr = std::max(worst_gyr, (s.gyr[k] - Vector3d(0, w, 0)).norm());
        // In the rotating sensor frame the centripetal acceleration points to the axis: -w^2 r along sensor x.
        worst_acc = std::max(worst_acc, (s.acc[k] - Vector3d(-w * w * r, kGravity, 0)).norm());
    }
    EXPECT_LT(worst_gyr, 2e-3);  // spline of the quaternion at 20 fps: w h = 0.075 rad per frame
    EXPECT_LT(worst_acc, 5e-3);  // of 0.45 m/s^2 centripetal
}

TEST(ImuSynthesis, VerticalBounceMatchesAnalyticSpecificForce) {
    // p_y = 1 + A sin(2 pi f t): a_y = g - A (2 pi f)^2 sin(2 pi f t) in the (unrotated) sensor frame.
    const double A = 0.05, f = 1.0, om = 2 * M_PI * f;
    const Motion m = sample(3.0, [&](double t, Vector3d& p, Quat& q) {
        p = {0, 1 + A * std::sin(om * t), 0};
        q = Quat::Identity();
    });
    const ImuSignals s = synthesize_imu(m.p, m.q, kSynthesisFps, 60);
    double worst = 0, worst_step = 0;
    for (size_t k = 0; k < s.t.size(); ++k) {
        worst = std::max(worst, std::fabs(s.acc[k].y() - (kGravity - A * om * om * std::sin(om * s.t[k]))));
        if (k) worst_step = std::max(worst_step, (s.acc[k] - s.acc[k - 1]).norm());
    }
    EXPECT_LT(worst, 0.02 * A * om * om + 1e-3);  // within 2 % of the 1.97 m/s^2 peak, edges included
    // Continuity: no sample-to-sample jump larger than the true signal's change over one sample (~0.21 m/s^2).
    EXPECT_LT(worst_step, 1.1 * A * om * om * om / 60);
}

TEST(ImuSynthesis, RefusesShortOrNonFiniteInput) {
    std::vector<Vector3d> p(3, Vector3d::Zero());
    std::vector<Quat> q(3, Quat::Identity());
    EXPECT_THROW(synthesize_imu(p, q, kSynthesisFps, 50), Error);
    p.resize(5, Vector3d::Zero());
    q.resize(5, Quat::Identity());
    p[2].x() = std::nan("");
    EXPECT_THROW(synthesize_imu(p, q, kSynthesisFps, 50), Error);
}

namespace {

// A sensor that keeps its orientation, shaken along `dir` by A sin(2 pi f t), sampled at 200 fps.
Motion shaken(const Vector3d& dir, double amplitude, double hz, double seconds) {
    Motion m;
    for (int f = 0; f <= static_cast<int>(seconds * 200); ++f) {
        m.p.push_back(Vector3d(0, 1, 0) + dir * amplitude * std::sin(2 * M_PI * hz * f / 200.0));
        m.q.push_back(Quat::Identity());
    }
    return m;
}

// Amplitude of the hz sinusoid in the accelerometer's `axis` over samples [from, end) (least squares on sin and cos).
double amplitude_at(const ImuSignals& s, int axis, double hz, size_t from) {
    double ss = 0, cc = 0, sc = 0, xs = 0, xc = 0;
    for (size_t k = from; k < s.t.size(); ++k) {
        const double si = std::sin(2 * M_PI * hz * s.t[k]), co = std::cos(2 * M_PI * hz * s.t[k]), x = s.acc[k][axis];
        ss += si * si, cc += co * co, sc += si * co, xs += x * si, xc += x * co;
    }
    const double det = ss * cc - sc * sc, a = (xs * cc - xc * sc) / det, b = (xc * ss - xs * sc) / det;
    return std::hypot(a, b);
}

}  // namespace

TEST(ImuSynthesis, StrapModeFiltersOnlyItsAxisByTheSpringMassTransferFunction) {
    // A mass on a spring of natural frequency fn and damping zeta, its base shaken at f = r fn, accelerates by
    // |H| times the base: |H| = sqrt(1 + (2 zeta r)^2) / sqrt((1 - r^2)^2 + (2 zeta r)^2).
    const double fn = 6, zeta = 0.25, A = 0.002;
    AttachmentDynamics strap;
    strap.strap = {fn, zeta};
    strap.strap_axis = Vector3d::UnitX();
    for (const double r : {1.0, 2.0}) {
        const double f = r * fn, base = A * std::pow(2 * M_PI * f, 2);
        const Motion m = shaken(Vector3d::UnitX(), A, f, 4.0);
        const ImuSignals s = synthesize_imu(m.p, m.q, 200, 1000, strap);
        const double h = std::hypot(1, 2 * zeta * r) / std::hypot(1 - r * r, 2 * zeta * r);
        EXPECT_NEAR(amplitude_at(s, 0, f, 2000) / base, h, 0.01 * h) << "r = " << r;  // transient gone after 2 s
        for (size_t k = 0; k < s.t.size(); ++k) {
            EXPECT_NEAR(s.acc[k].y(), kGravity, 1e-9);  // across the strap: gravity only
            EXPECT_NEAR(s.acc[k].z(), 0, 1e-9);
            EXPECT_LT(s.gyr[k].norm(), 1e-9);  // translation only
        }
    }
    // Shaken across the strap, the sensor reads what a bolted one reads.
    const Motion across = shaken(Vector3d(0, 0.6, 0.8), A, 6, 2.0);
    const ImuSignals bolted = synthesize_imu(across.p, across.q, 200, 1000),
                     on_strap = synthesize_imu(across.p, across.q, 200, 1000, strap);
    ASSERT_EQ(bolted.t.size(), on_strap.t.size());
    for (size_t k = 0; k < bolted.t.size(); ++k) EXPECT_LT((bolted.acc[k] - on_strap.acc[k]).norm(), 1e-9) << k;
}
