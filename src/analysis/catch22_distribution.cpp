// Distribution features: DN_HistogramMode and DN_OutlierInclude.
#include <algorithm>
#include <cmath>

#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

static double median(Series v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// DN_HistogramMode: the centre of the fullest of `num_bins` equal-width bins spanning [min, max] (the maximum
// falls in the last bin); when several bins tie, the mean of their centres.
double histogram_mode(const Series& x, int num_bins) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const double min = *lo, width = (*hi - *lo) / num_bins;
    std::vector<int> counts(num_bins, 0);
    for (double v : x) {
        int bin = static_cast<int>((v - min) / width);
        counts[std::min(std::max(bin, 0), num_bins - 1)]++;
    }
    const int most = *std::max_element(counts.begin(), counts.end());
    double centre_sum = 0.0;
    int ties = 0;
    for (int b = 0; b < num_bins; ++b)
        if (counts[b] == most) {
            centre_sum += min + (b + 0.5) * width;
            ++ties;
        }
    return centre_sum / ties;
}

// DN_OutlierInclude_{p,n}_001_mdrmd: thresholds 0, 0.01, ..., up to the largest value (of the series, or of
// its negation for the negative variant; the series is z-scored, so the steps are 0.01 standard deviations).
// At each threshold the samples at or above it are events; their median time index (1-based) as a position
// relative to the series' middle, median / (n / 2) - 1. Thresholds whose inter-event intervals (events - 1)
// make 0.02 or less of the samples on that side of the mean (values >= 0 of the possibly negated series) are
// trimmed from the top; the output is the median of the remaining positions.
double outlier_include_mdrmd(const Series& x, bool positive) {
    const double increment = 0.01, trim_percent = 2.0;
    const std::size_t n = x.size();
    Series y(n);
    for (std::size_t t = 0; t < n; ++t) y[t] = positive ? x[t] : -x[t];
    const double top = *std::max_element(y.begin(), y.end());
    const double on_side = static_cast<double>(std::count_if(y.begin(), y.end(), [](double v) { return v >= 0; }));
    const std::size_t num_thresholds = static_cast<std::size_t>(std::floor(top / increment)) + 1;
    Series positions;
    std::size_t keep = 0;
    for (std::size_t i = 0; i < num_thresholds; ++i) {
        const double threshold = static_cast<double>(i) * increment;
        Series events;
        for (std::size_t t = 0; t < n; ++t)
            if (y[t] >= threshold) events.push_back(static_cast<double>(t + 1));
        positions.push_back(events.empty() ? 0.0 : median(events) / (static_cast<double>(n) / 2.0) - 1.0);
        const double intervals = events.empty() ? 0.0 : static_cast<double>(events.size() - 1);
        if (intervals / on_side * 100.0 > trim_percent) keep = i + 1;
    }
    positions.resize(keep);
    return positions.empty() ? 0.0 : median(positions);
}

}  // namespace t2imu::catch22_detail
