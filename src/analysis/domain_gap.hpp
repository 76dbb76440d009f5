// The real-vs-synthetic comparison on two feature tables (catch22_table.hpp): the classifier two-sample test
// over all shared feature columns, per shared activity and overall, and the per-feature Wasserstein-1 and
// Kolmogorov-Smirnov distances (overall), as one JSON document.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/csv.hpp"

namespace t2imu {

nlohmann::json domain_gap(const CsvTable& real, const CsvTable& synthetic, uint64_t seed = 0);
// The pooled classifier two-sample balanced accuracy of a domain_gap document read from `path` (Error naming
// `path` and the key when it is missing).
double two_sample_balanced_accuracy(const nlohmann::json& gap, const std::string& path);

// The rows of `table` whose activity is one of `activities`: the pooled test over the classes two data sets
// share. Throws Error naming `option` for a class the table holds no row of.
CsvTable rows_of_activities(const CsvTable& table, const std::vector<std::string>& activities, const std::string& option);

}  // namespace t2imu
