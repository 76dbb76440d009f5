#include <gtest/gtest.h>

#include <cmath>

#include "core/npy.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "test_util.hpp"

using namespace t2imu;

static TimeSeries as_series(const NdArray& a) {
    const std::vector<double> v = a.to<double>();
    const int64_t rows = a.shape[0], cols = a.shape.size() > 1 ? a.shape[1] : 1;
    TimeSeries x(rows, cols);
    std::copy(v.begin(), v.end(), x.data());
    return x;
}

TEST(GaussianFilter, MatchesScipySigma20Nearest) {
    std::string in;
    SHARED_OR_SKIP(in, "reference/humanml3d/generated/helpers/gaussian_filter1d_in.npy");
    const TimeSeries x = as_series(read_npy(in));
    const TimeSeries expected = as_series(read_npy(
        test::shared_path("reference/humanml3d/generated/helpers/gaussian_filter1d_sigma20_nearest_axis0.npy")));
    const TimeSeries y = gaussian_filter1d_nearest(x, 20.0);
    ASSERT_EQ(y.rows(), expected.rows());
    EXPECT_LT((y - expected).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(GaussianFilter, KeepsConstantsAndLines) {
    // A constant is unchanged (weights sum to 1); a line is unchanged away from the edges (symmetric kernel).
    TimeSeries c = TimeSeries::Constant(50, 2, 3.5);
    EXPECT_LT((gaussian_filter1d_nearest(c, 2.0) - c).cwiseAbs().maxCoeff(), 1e-12);
    TimeSeries line(200, 1);
    for (int t = 0; t < 200; ++t) line(t, 0) = 0.25 * t;
    const TimeSeries y = gaussian_filter1d_nearest(line, 3.0);
    for (int t = 20; t < 180; ++t) EXPECT_NEAR(y(t, 0), line(t, 0), 1e-12);
    // At the start, 'nearest' repeats the first sample, so the filtered value is pulled up, never down.
    EXPECT_GT(y(0, 0), line(0, 0));
}
