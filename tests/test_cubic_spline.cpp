#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/signal/cubic_spline.hpp"

using namespace t2imu;

TEST(CubicSpline, ReproducesCubicsExactly) {
    // Not-a-knot ends make the spline exact for any cubic, derivatives included.
    CubicSpline::Samples y(12, 1);
    auto f = [](double t) { return 0.5 - 2 * t + 3 * t * t - 1.5 * t * t * t; };
    for (int i = 0; i < 12; ++i) y(i, 0) = f(0.1 * i);
    const CubicSpline s(y, 0.1);
    Eigen::VectorXd v, d1, d2;
    for (double t : {0.0, 0.033, 0.47, 1.02, 1.1}) {
        s.evaluate(t, &v, &d1, &d2);
        EXPECT_NEAR(v[0], f(t), 1e-12);
        EXPECT_NEAR(d1[0], -2 + 6 * t - 4.5 * t * t, 1e-10);
        EXPECT_NEAR(d2[0], 6 - 9 * t, 1e-9);
    }
}

TEST(CubicSpline, SecondDerivativeOfASineConvergesAsHSquared) {
    // y = sin(2 pi t) sampled at 20 and 40 Hz: the acceleration error falls about 4x when h halves.
    auto max_error = [](double fps) {
        const int n = static_cast<int>(2 * fps) + 1;
        CubicSpline::Samples y(n, 1);
        for (int i = 0; i < n; ++i) y(i, 0) = std::sin(2 * M_PI * i / fps);
        const CubicSpline s(y, 1 / fps);
        double worst = 0;
        Eigen::VectorXd d2;
        for (double t = 0; t <= 2.0; t += 0.001) {
            s.evaluate(t, nullptr, nullptr, &d2);
            worst = std::max(worst, std::fabs(d2[0] + 4 * M_PI * M_PI * std::sin(2 * M_PI * t)));
        }
        return worst;
    };
    const double e20 = max_error(20), e40 = max_error(40);
    EXPECT_LT(e20, 0.05 * 4 * M_PI * M_PI);  // within 5 % of the peak, edges included
    EXPECT_GT(e20 / e40, 3.0);
}

TEST(CubicSpline, NeedsFourSamples) { EXPECT_THROW(CubicSpline(CubicSpline::Samples::Zero(3, 2), 0.05), Error); }
