// The real-vs-synthetic comparison on two feature tables (catch22_table.hpp): the classifier two-sample test
// over all shared feature columns, per shared activity and overall, and the per-feature Wasserstein-1 and
// Kolmogorov-Smirnov distances (overall), as one JSON document.
#pragma once
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/csv.hpp"

namespace t2imu {

// The classifier two-sample test on one pair of window sets (two_sample.hpp): 0.5 = indistinguishable.
struct TwoSampleSummary {
    double balanced_accuracy = 0;
    std::vector<double> folds;        // each fold's balanced accuracy
    int64_t real = 0, synthetic = 0;  // windows
};

struct FeatureDistance {
    std::string feature;
    double wasserstein_1 = 0, ks = 0;  // NaN where a side holds no finite value
};

// A domain-gap result (`t2imu analysis domain-gap`, an experiment's gap/): its one schema, written and read here.
struct DomainGap {
    int64_t features = 0;  // feature columns the tables share
    TwoSampleSummary overall;
    std::map<std::string, TwoSampleSummary> per_activity;  // activities with at least 5 windows on each side
    std::vector<FeatureDistance> per_feature;              // most different first (by KS)
};

DomainGap domain_gap(const CsvTable& real, const CsvTable& synthetic, uint64_t seed = 0);
nlohmann::json domain_gap_json(const DomainGap& gap);
// Error naming `path` and the dotted key ("per_feature.2.ks") when a field is missing or mistyped.
DomainGap parse_domain_gap(const nlohmann::json& doc, const std::string& path);
DomainGap read_domain_gap(const std::string& path);

// The rows of `table` whose activity is one of `activities`: the pooled test over the classes two data sets
// share. Throws Error naming `option` for a class the table holds no row of.
CsvTable rows_of_activities(const CsvTable& table, const std::vector<std::string>& activities,
                            const std::string& option);

}  // namespace t2imu
