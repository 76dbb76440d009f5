// The evaluation's figures (after the paper's): L_acc change per activity category (Fig. 1), t-SNE of real vs
// synthetic features (Fig. 2), balanced accuracy per model (Fig. 3), confusion matrices, signal statistics per
// activity, and IMU traces.
// Each takes the file the producing command wrote, as parsed there, and draws one PNG.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/csv.hpp"
#include "har/har_result.hpp"
#include "har/low_data_curve.hpp"
#include "report/signal_stats.hpp"

namespace t2imu {

// `t2imu analysis lacc` output: bars of change_percent per group.
void plot_lacc_change(const CsvTable& lacc, const std::string& png);
// A t-SNE table (tsne_x, tsne_y) coloured by `colour_column` (e.g. source: real / synthetic); rows whose
// `filter_column` value is not in `keep` are left out when keep is non-empty.
void plot_tsne(const CsvTable& tsne, const std::string& colour_column, const std::string& png, const std::string& title,
               const std::string& filter_column = "", const std::vector<std::string>& keep = {});
// `t2imu har run` results: mean balanced accuracy with the standard deviation over runs, one bar per result.
void plot_balanced_accuracy(const std::vector<std::pair<std::string, HarResult>>& results, const std::string& png);
// A result's summed confusion matrix, each row normalised to recall.
void plot_confusion(const HarResult& result, const std::string& png, const std::string& title);
// A low-data curve: balanced accuracy (%) against K real training subjects, one line per arm with a band of ± one sd
// over the draws; K at even spacing (0, 1, 2, 4, 8, all), a point only where the arm has that K.
void plot_low_data_curve(const LowDataCurve& curve, const std::string& png);
// Per-recording signal statistics by activity, synthetic beside real where there is real data: acceleration
// magnitude sd (left) and dominant frequency (right), one point per recording (jittered sideways), a bar at
// each median.
void plot_signal_stats(const std::vector<ActivityStats>& groups, const std::string& png, const std::string& title);
// An IMU recording (t, acc_xyz, gyr_xyz): accelerometer above, gyroscope below.
void plot_imu_trace(const CsvTable& recording, const std::string& png, const std::string& title);

}  // namespace t2imu
