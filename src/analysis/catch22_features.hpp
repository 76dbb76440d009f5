// The individual catch22 features and the helpers they share (internal to src/analysis). Every feature takes
// the z-scored series (mean 0, sample standard deviation 1) unless its comment says otherwise.
#pragma once
#include <cstddef>
#include <vector>

namespace t2imu::catch22_detail {

using Series = std::vector<double>;

// --- shared statistics (catch22_stats.cpp) ---
double mean(const Series& x);
double sample_std(const Series& x);  // divides by n - 1
// Autocorrelation r(k) = sum_t (x_t - m)(x_{t+k} - m) / sum_t (x_t - m)^2 for k = 0..n-1 (biased estimator,
// computed by FFT with zero padding so that it is linear, not circular).
Series autocorrelation(const Series& x);
// The first lag k >= 1 where the autocorrelation drops to zero or below (CO_FirstZero 'ac'); n if never.
std::size_t first_zero_crossing(const Series& acf);
// Symbols 1..numGroups of x by its quantiles (SB_CoarseGrain 'quantile'): x falls in group g when it lies
// above the (g-1)/numGroups quantile and at or below the g/numGroups quantile.
std::vector<int> coarse_grain_quantile(const Series& x, int num_groups);
// Slope and intercept of the least-squares line y = a x + b.
void linear_fit(const Series& x, const Series& y, double& slope, double& intercept);

// --- distribution (catch22_distribution.cpp) ---
double histogram_mode(const Series& x, int num_bins);          // DN_HistogramMode_5 / _10
double outlier_include_mdrmd(const Series& x, bool positive);  // DN_OutlierInclude_p/n_001_mdrmd

// --- autocorrelation and linear structure (catch22_autocorrelation.cpp) ---
double first_1_e_crossing(const Series& acf);                            // CO_f1ecac
double first_minimum(const Series& acf);                                 // CO_FirstMin_ac
double histogram_ami_even(const Series& x, int tau, int num_bins);       // CO_HistogramAMI_even_2_5
double time_reversibility(const Series& x);                              // CO_trev_1_num
double gaussian_ami_first_minimum(const Series& x, int max_tau);         // IN_AutoMutualInfoStats_40_gaussian_fmmi
double embed2_dist_expfit_meandiff(const Series& x, const Series& acf);  // CO_Embed2_Dist_tau_d_expfit_meandiff

// --- forecasting (catch22_forecast.cpp) ---
double local_mean3_stderr(const Series& x);                        // FC_LocalSimple_mean3_stderr
double local_mean1_tauresrat(const Series& x, const Series& acf);  // FC_LocalSimple_mean1_tauresrat

// --- symbolic dynamics and increments (catch22_symbolic.cpp) ---
double pnn40(const Series& x);                                                // MD_hrv_classic_pnn40
double binary_mean_longstretch1(const Series& x);                             // SB_BinaryStats_mean_longstretch1
double binary_diff_longstretch0(const Series& x);                             // SB_BinaryStats_diff_longstretch0
double motif_three_quantile_hh(const Series& x);                              // SB_MotifThree_quantile_hh
double transition_matrix_3ac_sumdiagcov(const Series& x, const Series& acf);  // SB_TransitionMatrix_3ac_sumdiagcov

// --- spectrum (catch22_spectral.cpp) ---
double welch_rect_area_5_1(const Series& x);  // SP_Summaries_welch_rect_area_5_1
double welch_rect_centroid(const Series& x);  // SP_Summaries_welch_rect_centroid

// --- periodicity (catch22_periodicity.cpp) ---
double periodicity_wang(const Series& x, double threshold);  // PD_PeriodicityWang_th0_01

// --- fluctuation analysis (catch22_fluctuation.cpp) ---
double fluct_anal_rsrangefit_prop_r1(const Series& x);  // SC_FluctAnal_2_rsrangefit_50_1_logi_prop_r1
double fluct_anal_dfa_prop_r1(const Series& x);         // SC_FluctAnal_2_dfa_50_1_2_logi_prop_r1

}  // namespace t2imu::catch22_detail
