// A feature table (CSV rows of windows, e.g. catch22_table.hpp's) -> its 2-D t-SNE embedding as a table the
// report plots: the label columns carried over, then tsne_x, tsne_y.
//
// Features on very different scales (catch22 mixes counts, lags and fractions) are standardised per column
// first (zero mean, unit standard deviation over the rows; a constant column becomes 0). A missing value ("nan":
// catch22 of a constant channel) is put at its column's mean, i.e. 0 after standardising, so one flat window does
// not take its row out of the plot.
#pragma once
#include <set>
#include <string>

#include "analysis/tsne.hpp"
#include "core/csv.hpp"

namespace t2imu {

struct TsneTable {
    CsvTable embedding;    // label columns, tsne_x, tsne_y
    PointMatrix features;  // [N, D] standardised, as embedded
    TsneResult result;
    size_t feature_columns = 0;
};

// Columns named in `label_columns`, and columns holding any non-numeric value, are labels; the others are
// features. Throws Error naming `what` when no row or no feature column is left.
TsneTable tsne_table(const CsvTable& table, const std::set<std::string>& label_columns, const TsneOptions& options,
                     const std::string& what);

}  // namespace t2imu
