// Features of the autocorrelation and of the lagged joint distribution: CO_f1ecac, CO_FirstMin_ac,
// CO_HistogramAMI_even_2_5, CO_trev_1_num, IN_AutoMutualInfoStats_40_gaussian_fmmi and
// CO_Embed2_Dist_tau_d_expfit_meandiff.
#include <algorithm>
#include <cmath>

#include "analysis/catch22_features.hpp"

namespace t2imu::catch22_detail {

// CO_f1ecac: the lag at which the autocorrelation first falls below 1/e, linearly interpolated between the
// two integer lags around the crossing (the catch22 variant; hctsa's original returns the integer lag).
double first_1_e_crossing(const Series& acf) {
    const double threshold = 1.0 / std::exp(1.0);
    for (std::size_t k = 1; k < acf.size(); ++k)
        if (acf[k] < threshold) {
            const double fraction = (acf[k - 1] - threshold) / (acf[k - 1] - acf[k]);
            return static_cast<double>(k - 1) + fraction;
        }
    return static_cast<double>(acf.size());
}

// CO_FirstMin_ac: the first lag at which the autocorrelation has a strict local minimum.
double first_minimum(const Series& acf) {
    for (std::size_t k = 1; k + 1 < acf.size(); ++k)
        if (acf[k] < acf[k - 1] && acf[k] < acf[k + 1]) return static_cast<double>(k);
    return static_cast<double>(acf.size());
}

// CO_HistogramAMI_even_2_5: the automutual information (natural log) at lag `tau` of the series discretised
// into `num_bins` equal-width bins. hctsa's 'even' edges span [min - 0.1, max + 0.1]; the marginals are the
// row and column sums of the joint histogram of (x_t, x_{t+tau}).
double histogram_ami_even(const Series& x, int tau, int num_bins) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const double first_edge = *lo - 0.1, width = (*hi - *lo + 0.2) / num_bins;
    auto bin_of = [&](double v) { return std::min(static_cast<int>((v - first_edge) / width), num_bins - 1); };
    const std::size_t pairs = x.size() - static_cast<std::size_t>(tau);
    std::vector<double> joint(num_bins * num_bins, 0.0), rows(num_bins, 0.0), cols(num_bins, 0.0);
    for (std::size_t t = 0; t < pairs; ++t) joint[bin_of(x[t]) * num_bins + bin_of(x[t + tau])] += 1.0;
    for (int i = 0; i < num_bins; ++i)
        for (int j = 0; j < num_bins; ++j) {
            joint[i * num_bins + j] /= static_cast<double>(pairs);
            rows[i] += joint[i * num_bins + j];
            cols[j] += joint[i * num_bins + j];
        }
    double ami = 0.0;
    for (int i = 0; i < num_bins; ++i)
        for (int j = 0; j < num_bins; ++j) {
            const double p = joint[i * num_bins + j];
            if (p > 0.0) ami += p * std::log(p / (rows[i] * cols[j]));
        }
    return ami;
}

// CO_trev_1_num: the mean cubed increment at lag 1, a measure of time-reversal asymmetry.
double time_reversibility(const Series& x) {
    double sum = 0.0;
    for (std::size_t t = 0; t + 1 < x.size(); ++t) sum += std::pow(x[t + 1] - x[t], 3);
    return sum / static_cast<double>(x.size() - 1);
}

// IN_AutoMutualInfoStats_40_gaussian_fmmi: for Gaussian variables the mutual information is -log(1 - r^2) / 2,
// with r here the Pearson correlation of x_t and x_{t+k} over their overlap (hctsa's 'gaussian' estimator).
// It is taken for lags k = 1..min(40, ceil(n/2)); the output is the first lag at which it has a local minimum.
static double pearson_at_lag(const Series& x, std::size_t lag) {
    const Series head(x.begin(), x.end() - lag), tail(x.begin() + lag, x.end());
    const double mh = mean(head), mt = mean(tail);
    double sht = 0.0, shh = 0.0, stt = 0.0;
    for (std::size_t t = 0; t < head.size(); ++t) {
        sht += (head[t] - mh) * (tail[t] - mt);
        shh += (head[t] - mh) * (head[t] - mh);
        stt += (tail[t] - mt) * (tail[t] - mt);
    }
    return sht / std::sqrt(shh * stt);
}

double gaussian_ami_first_minimum(const Series& x, int max_tau) {
    const std::size_t n = x.size();
    const std::size_t num_taus = std::min<std::size_t>(max_tau, (n + 1) / 2);
    Series ami(num_taus);
    for (std::size_t i = 0; i < num_taus; ++i) {
        const double r = pearson_at_lag(x, i + 1);
        ami[i] = -0.5 * std::log(1.0 - r * r);
    }
    for (std::size_t i = 1; i + 1 < num_taus; ++i)
        if (ami[i] < ami[i - 1] && ami[i] < ami[i + 1]) return static_cast<double>(i);
    return static_cast<double>(num_taus);
}

// CO_Embed2_Dist_tau_d_expfit_meandiff: embed the series in two dimensions, (x_t, x_{t+tau}) with tau the first
// zero crossing of the autocorrelation (at most n/10), and take the distances between successive points. Fit
// an exponential distribution (its mean) to them and return the mean absolute difference between the
// histogram of the distances (as probabilities) and the fitted density at the bin
// centres.
double embed2_dist_expfit_meandiff(const Series& x, const Series& acf) {
    const std::size_t n = x.size();
    std::size_t tau = first_zero_crossing(acf);
    if (static_cast<double>(tau) > static_cast<double>(n) / 10.0) tau = n / 10;
    Series d(n - tau - 1);
    for (std::size_t t = 0; t + 1 < n - tau; ++t) d[t] = std::hypot(x[t + 1] - x[t], x[t + tau + 1] - x[t + tau]);
    const double lambda = mean(d);
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    // Scott's rule picks the number of bins; the bins then split [min, max] evenly.
    const double scott_width = 3.5 * sample_std(d) / std::cbrt(static_cast<double>(d.size()));
    const int num_bins = static_cast<int>(std::ceil((*hi - *lo) / scott_width));
    const double width = (*hi - *lo) / num_bins;
    std::vector<double> counts(num_bins, 0.0);
    for (double v : d) counts[std::min(static_cast<int>((v - *lo) / width), num_bins - 1)] += 1.0;
    double diff_sum = 0.0;
    for (int b = 0; b < num_bins; ++b) {
        const double centre = *lo + (b + 0.5) * width;
        const double fitted = std::exp(-centre / lambda) / lambda;
        diff_sum += std::fabs(counts[b] / static_cast<double>(d.size()) - fitted);
    }
    return diff_sum / num_bins;
}

}  // namespace t2imu::catch22_detail
