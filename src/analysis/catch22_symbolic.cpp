// Features of the series as symbols: MD_hrv_classic_pnn40, SB_BinaryStats, SB_MotifThree_quantile_hh and
// SB_TransitionMatrix_3ac_sumdiagcov.
#include <algorithm>
#include <cmath>

#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

// MD_hrv_classic_pnn40: from heart-rate variability, the share of successive differences larger than 40 ms,
// with the series read as seconds, i.e. |x_{t+1} - x_t| > 0.04.
double pnn40(const Series& x) {
    std::size_t count = 0;
    for (std::size_t t = 0; t + 1 < x.size(); ++t)
        if (std::fabs(x[t + 1] - x[t]) * 1000.0 > 40.0) ++count;
    return static_cast<double>(count) / static_cast<double>(x.size() - 1);
}

// The longest stretch of `symbol` in `bits` as the catch22 reference measures it: the largest distance between
// successive occurrences of the other symbol, scanning from index 0 up to `last` (n - 2 for a series of n
// samples, whatever the length of `bits`), which also closes the final stretch. An interior run of length L
// thus counts L + 1 and one touching either end of the scan one less. The reference outputs follow this
// convention, so we keep it.
static double longest_stretch(const std::vector<int>& bits, int symbol, std::size_t last) {
    std::size_t longest = 0, last_other = 0;
    for (std::size_t i = 0; i <= last; ++i)
        if (bits[i] != symbol || i == last) {
            longest = std::max(longest, i - last_other);
            last_other = i;
        }
    return static_cast<double>(longest);
}

// SB_BinaryStats_mean_longstretch1: the longest run of consecutive values above the mean.
double binary_mean_longstretch1(const Series& x) {
    const double m = mean(x);
    std::vector<int> bits(x.size());
    for (std::size_t t = 0; t < x.size(); ++t) bits[t] = x[t] > m ? 1 : 0;
    return longest_stretch(bits, 1, x.size() - 2);
}

// SB_BinaryStats_diff_longstretch0: the longest run of consecutive decreases (negative increments).
double binary_diff_longstretch0(const Series& x) {
    std::vector<int> bits(x.size() - 1);
    for (std::size_t t = 0; t + 1 < x.size(); ++t) bits[t] = x[t + 1] - x[t] < 0 ? 0 : 1;
    return longest_stretch(bits, 0, x.size() - 2);
}

// Counts of the transitions symbol i -> symbol j (symbols 1..3) between successive samples.
static std::vector<std::vector<double>> transition_counts(const std::vector<int>& symbols, int num_groups) {
    std::vector<std::vector<double>> counts(num_groups, std::vector<double>(num_groups, 0.0));
    for (std::size_t t = 0; t + 1 < symbols.size(); ++t) counts[symbols[t] - 1][symbols[t + 1] - 1] += 1.0;
    return counts;
}

// SB_MotifThree_quantile_hh: the Shannon entropy (natural log) of the two-letter words of the series coarse
// grained into three equiprobable symbols.
double motif_three_quantile_hh(const Series& x) {
    const auto counts = transition_counts(coarse_grain_quantile(x, 3), 3);
    const double words = static_cast<double>(x.size() - 1);
    double entropy = 0.0;
    for (const auto& row : counts)
        for (double c : row)
            if (c > 0.0) entropy -= (c / words) * std::log(c / words);
    return entropy;
}

// SB_TransitionMatrix_3ac_sumdiagcov: downsample the series by the first zero crossing of its
// autocorrelation, coarse grain it into three equiprobable symbols, and sum the variances of the columns of
// the resulting transition-probability matrix (the trace of the covariance of its columns).
double transition_matrix_3ac_sumdiagcov(const Series& x, const Series& acf) {
    const int num_groups = 3;
    const std::size_t tau = first_zero_crossing(acf);
    Series downsampled;
    for (std::size_t t = 0; t < x.size(); t += tau) downsampled.push_back(x[t]);
    auto matrix = transition_counts(coarse_grain_quantile(downsampled, num_groups), num_groups);
    for (auto& row : matrix)
        for (double& p : row) p /= static_cast<double>(downsampled.size() - 1);
    double sum_variances = 0.0;
    for (int j = 0; j < num_groups; ++j) {
        double column_mean = 0.0;
        for (int i = 0; i < num_groups; ++i) column_mean += matrix[i][j] / num_groups;
        for (int i = 0; i < num_groups; ++i)
            sum_variances += (matrix[i][j] - column_mean) * (matrix[i][j] - column_mean) / (num_groups - 1);
    }
    return sum_variances;
}

}  // namespace t2imu::catch22_detail
