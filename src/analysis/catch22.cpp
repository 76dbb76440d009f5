// catch22 / catch24: checks the series, z-scores it and computes every feature in the canonical order.
#include "analysis/catch22.hpp"

#include <cmath>
#include <fstream>

#include "analysis/catch22_features.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"

namespace t2imu {

const std::vector<std::string>& catch24_names() {
    static const std::vector<std::string> names = {"DN_HistogramMode_5",
                                                   "DN_HistogramMode_10",
                                                   "DN_OutlierInclude_p_001_mdrmd",
                                                   "DN_OutlierInclude_n_001_mdrmd",
                                                   "CO_f1ecac",
                                                   "CO_FirstMin_ac",
                                                   "SP_Summaries_welch_rect_area_5_1",
                                                   "SP_Summaries_welch_rect_centroid",
                                                   "FC_LocalSimple_mean3_stderr",
                                                   "FC_LocalSimple_mean1_tauresrat",
                                                   "MD_hrv_classic_pnn40",
                                                   "SB_BinaryStats_mean_longstretch1",
                                                   "SB_BinaryStats_diff_longstretch0",
                                                   "SB_MotifThree_quantile_hh",
                                                   "CO_HistogramAMI_even_2_5",
                                                   "CO_trev_1_num",
                                                   "IN_AutoMutualInfoStats_40_gaussian_fmmi",
                                                   "SB_TransitionMatrix_3ac_sumdiagcov",
                                                   "PD_PeriodicityWang_th0_01",
                                                   "CO_Embed2_Dist_tau_d_expfit_meandiff",
                                                   "SC_FluctAnal_2_rsrangefit_50_1_logi_prop_r1",
                                                   "SC_FluctAnal_2_dfa_50_1_2_logi_prop_r1",
                                                   "DN_Mean",
                                                   "DN_Spread_Std"};
    return names;
}

const std::vector<std::string>& catch24_short_names() {
    static const std::vector<std::string> names = {"mode_5",
                                                   "mode_10",
                                                   "outlier_timing_pos",
                                                   "outlier_timing_neg",
                                                   "acf_timescale",
                                                   "acf_first_min",
                                                   "low_freq_power",
                                                   "centroid_freq",
                                                   "forecast_error",
                                                   "whiten_timescale",
                                                   "high_fluctuation",
                                                   "stretch_high",
                                                   "stretch_decreasing",
                                                   "entropy_pairs",
                                                   "ami2",
                                                   "trev",
                                                   "ami_timescale",
                                                   "transition_variance",
                                                   "periodicity",
                                                   "embedding_dist",
                                                   "rs_range",
                                                   "dfa",
                                                   "mean",
                                                   "std"};
    return names;
}

std::vector<std::size_t> catch22_reference_output_order(bool catch24) {
    // The reference CLI prints the features grouped as its source lists them, not in featureList order.
    std::vector<std::size_t> order = {3, 2, 0, 1, 19, 4, 5, 14, 15, 9, 8, 16, 10, 12, 11, 13, 20, 21, 6, 7, 17, 18};
    if (catch24) order.insert(order.end(), {22, 23});
    return order;
}

std::vector<double> read_catch22_series(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path, "file", "a readable series file (one number per line)", "cannot open");
    std::vector<double> series;
    std::string token;
    while (in >> token) {
        const std::optional<double> v = parse_number(token);
        if (!v) throw Error(path, "value " + std::to_string(series.size() + 1), "a number", token);
        series.push_back(*v);
    }
    return series;
}

// The reference refuses series it cannot z-score or whose features would be meaningless; so do we.
static void check_series(const std::vector<double>& x, const std::string& source) {
    if (x.size() < kCatch22MinLength)
        throw Error(source, "length", "at least " + std::to_string(kCatch22MinLength) + " samples for catch22",
                    std::to_string(x.size()));
    for (std::size_t t = 0; t < x.size(); ++t)
        if (!std::isfinite(x[t]))
            throw Error(source, "value " + std::to_string(t + 1), "finite numbers only for catch22",
                        std::isnan(x[t]) ? "NaN" : (x[t] > 0 ? "inf" : "-inf"));
    for (double v : x)
        if (v != x.front()) return;
    throw Error(source, "values", "a series that is not constant (catch22 z-scores it)",
                "every value " + std::to_string(x.front()));
}

std::vector<double> catch22(const std::vector<double>& series, bool catch24, const std::string& source) {
    using namespace catch22_detail;
    check_series(series, source);
    const double m = mean(series), sd = sample_std(series);
    Series z(series.size());
    for (std::size_t t = 0; t < series.size(); ++t) z[t] = (series[t] - m) / sd;
    const Series acf = autocorrelation(z);
    std::vector<double> out = {
        histogram_mode(z, 5),
        histogram_mode(z, 10),
        outlier_include_mdrmd(z, true),
        outlier_include_mdrmd(z, false),
        first_1_e_crossing(acf),
        first_minimum(acf),
        welch_rect_area_5_1(z),
        welch_rect_centroid(z),
        local_mean3_stderr(z),
        local_mean1_tauresrat(z, acf),
        pnn40(z),
        binary_mean_longstretch1(z),
        binary_diff_longstretch0(z),
        motif_three_quantile_hh(z),
        histogram_ami_even(z, 2, 5),
        time_reversibility(z),
        gaussian_ami_first_minimum(z, 40),
        transition_matrix_3ac_sumdiagcov(z, acf),
        periodicity_wang(z, 0.01),
        embed2_dist_expfit_meandiff(z, acf),
        fluct_anal_rsrangefit_prop_r1(z),
        fluct_anal_dfa_prop_r1(z),
    };
    if (catch24) {
        out.push_back(m);
        out.push_back(sd);
    }
    return out;
}

}  // namespace t2imu
