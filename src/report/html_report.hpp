// `t2imu report`: every result file found under a folder -> PNG figures and one self-contained HTML page
// (the figures embedded as base64 data URIs, so the page can be mailed or archived alone; only the links to
// the synthetic motions' BVH files point outside it, relative to the report folder).
//
// Recognised by content, anywhere under the folder:
//   HAR results (har/har_result.hpp's JSON, read typed)       -> balanced accuracy per result, confusion matrices
//   low-data curves (har/low_data_curve.hpp's JSON)           -> accuracy against K real subjects per arm, a table
//   L_acc analyses (CSV with group, change_percent)          -> L_acc change per category
//   t-SNE tables (CSV with tsne_x, tsne_y)                    -> scatter by `source` (or the first label column),
//                                                               and for high-dynamic activities when labelled
//   domain-gap results (JSON with classifier_two_sample_test) -> a table
//   synthesis folders (t2imu synth's synth_report.json)      -> kept/dropped motions per activity, time taken;
//                                                               per kept motion a pose strip, its prompt, quality and
//                                                               activity-check outcome, a link to its BVH; signal
//                                                               statistics per activity, beside real_dir's
//                                                               (report/synth_section.hpp). Titled by the folder's
//                                                               path under the results folder, or its own name
//   IMU recordings (CSV starting t,acc_x,...)                  -> traces of the first three
#pragma once
#include <string>

namespace t2imu {

struct ReportSummary {
    int figures = 0, synth_reports = 0, har_results = 0, low_data_curves = 0, lacc_tables = 0, tsne_tables = 0,
        gap_results = 0, traces = 0;
};

// `real_dir`: a real IMU data set (imu/imu_dataset.hpp layout) to compare the synthetic signals with; "" for none.
ReportSummary write_report(const std::string& results_dir, const std::string& report_dir,
                           const std::string& real_dir = "");

}  // namespace t2imu
