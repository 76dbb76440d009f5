// The real-vs-synthetic comparison on two feature tables (catch22_table.hpp): the classifier two-sample test
// over all shared feature columns, per shared activity and overall, and the per-feature Wasserstein-1 and
// Kolmogorov-Smirnov distances (overall), as one JSON document.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/csv.hpp"

namespace t2imu {

nlohmann::json domain_gap(const CsvTable& real, const CsvTable& synthetic, uint64_t seed = 0);

}  // namespace t2imu
