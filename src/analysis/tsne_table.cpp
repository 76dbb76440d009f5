#include "analysis/tsne_table.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/parse.hpp"

namespace t2imu {

namespace {

bool is_missing(const std::string& s) { return s == "nan" || s == "NaN" || s == "-nan"; }

void standardise_columns(PointMatrix& x) {
    for (Eigen::Index c = 0; c < x.cols(); ++c) {
        double sum = 0, sum_sq = 0, n = 0;
        for (Eigen::Index r = 0; r < x.rows(); ++r)
            if (std::isfinite(x(r, c))) sum += x(r, c), sum_sq += x(r, c) * x(r, c), n += 1;
        const double mean = n > 0 ? sum / n : 0.0;
        const double sd = n > 0 ? std::sqrt(std::max(sum_sq / n - mean * mean, 0.0)) : 0.0;
        for (Eigen::Index r = 0; r < x.rows(); ++r)
            x(r, c) = std::isfinite(x(r, c)) && sd > 1e-12 ? (x(r, c) - mean) / sd : 0.0;
    }
}

}  // namespace

TsneTable tsne_table(const CsvTable& table, const std::set<std::string>& label_columns, const TsneOptions& options,
                     const std::string& what) {
    if (table.rows.empty()) throw Error(what, "rows", "at least one data row");
    std::vector<size_t> features, labels;
    for (size_t c = 0; c < table.header.size(); ++c) {
        bool numeric = label_columns.count(table.header[c]) == 0;
        for (const auto& row : table.rows) numeric = numeric && (parse_number(row[c]) || is_missing(row[c]));
        (numeric ? features : labels).push_back(c);
    }
    if (features.empty()) throw Error(what, "columns", "numeric feature columns");
    TsneTable out;
    out.feature_columns = features.size();
    out.features.resize(static_cast<Eigen::Index>(table.rows.size()), static_cast<Eigen::Index>(features.size()));
    for (size_t r = 0; r < table.rows.size(); ++r)
        for (size_t f = 0; f < features.size(); ++f) {
            const std::string& v = table.rows[r][features[f]];
            out.features(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(f)) =
                is_missing(v) ? NAN : *parse_number(v);  // numeric: checked above
        }
    standardise_columns(out.features);
    out.result = tsne(out.features, options);
    for (size_t c : labels) out.embedding.header.push_back(table.header[c]);
    out.embedding.header.push_back("tsne_x");
    out.embedding.header.push_back("tsne_y");
    for (size_t r = 0; r < table.rows.size(); ++r) {
        std::vector<std::string> row;
        for (size_t c : labels) row.push_back(table.rows[r][c]);
        for (int d = 0; d < 2; ++d) {
            row.push_back(general_text(out.result.embedding(static_cast<Eigen::Index>(r), d), 6));
        }
        out.embedding.rows.push_back(row);
    }
    return out;
}

}  // namespace t2imu
