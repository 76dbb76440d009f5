// The paper's Fig. 1 in numbers: how the acceleration loss L_acc of generated motions changes per activity
// category between a model and its fine-tuned version.
//
// Input: two per-sample CSVs (the diffusion stage's `t2imu eval-lacc`), columns `id,caption,l_acc`, evaluated on
// the same samples with the same noise (rows are matched by id). Output per category: samples, mean L_acc
// before and after, and the relative change 100 (after - before) / before in %; the same for the high-dynamic
// (Dancing, Jumping, Running) and low-dynamic (the rest except Other) groups and for all samples.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "analysis/activity_categories.hpp"

namespace t2imu {

struct LaccGroup {
    std::string name;
    size_t samples = 0;
    double before = 0, after = 0;  // mean L_acc
    double change_percent() const { return before > 0 ? 100.0 * (after - before) / before : 0.0; }
};

struct LaccAnalysis {
    std::vector<LaccGroup> categories;  // kActivityCategories then Other; empty ones left out
    LaccGroup high_dynamic, low_dynamic, all;
};

struct LaccSample {
    std::string id, caption;
    double l_acc = 0;
};
std::vector<LaccSample> read_lacc_csv(const std::string& path);

LaccAnalysis analyse_lacc(const std::vector<LaccSample>& before, const std::vector<LaccSample>& after,
                          const ActivityCategorizer& categorizer);
std::string lacc_analysis_csv(const LaccAnalysis& a);  // group,samples,l_acc_before,l_acc_after,change_percent

}  // namespace t2imu
