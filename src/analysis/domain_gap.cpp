#include "analysis/domain_gap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "analysis/two_sample.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"

namespace t2imu {

namespace {

const std::set<std::string> kLabelColumns = {"subject", "trial", "activity", "window"};

PointMatrix columns_of(const CsvTable& t, const std::vector<std::string>& names, const std::string& activity) {
    std::vector<size_t> rows;
    const bool filter = !activity.empty();
    for (size_t r = 0; r < t.rows.size(); ++r)
        if (!filter || t.rows[r][t.column("activity")] == activity) rows.push_back(r);
    PointMatrix x(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(names.size()));
    for (size_t c = 0; c < names.size(); ++c) {
        const size_t col = t.column(names[c]);
        for (size_t r = 0; r < rows.size(); ++r) {
            const std::string& v = t.rows[rows[r]][col];
            // catch22 writes "nan" (or nothing) for a feature of a flat channel; anything else must be a number.
            x(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v.empty() ? std::nan("") : t.number(rows[r], col);
        }
    }
    return x;
}

nlohmann::json test_json(const PointMatrix& a, const PointMatrix& b, uint64_t seed) {
    const TwoSampleResult r = classifier_two_sample_test(a, b, 5, seed);
    return {{"balanced_accuracy", r.balanced_accuracy}, {"folds", r.fold_accuracy}, {"real", a.rows()}, {"synthetic", b.rows()}};
}

}  // namespace

nlohmann::json domain_gap(const CsvTable& real, const CsvTable& synthetic, uint64_t seed) {
    std::vector<std::string> features;
    for (const std::string& h : real.header)
        if (!kLabelColumns.count(h) && std::find(synthetic.header.begin(), synthetic.header.end(), h) != synthetic.header.end()) features.push_back(h);
    if (features.empty()) throw Error(real.source, "columns", "feature columns shared with " + synthetic.source);
    const PointMatrix a = columns_of(real, features, ""), b = columns_of(synthetic, features, "");
    nlohmann::json out;
    out["features"] = features.size();
    out["classifier_two_sample_test"] = test_json(a, b, seed);
    out["note"] = "balanced accuracy of logistic regression telling real (0) from synthetic (1), 5-fold CV: 0.5 = indistinguishable";
    nlohmann::json per_activity = nlohmann::json::object();
    if (real.has_column("activity") && synthetic.has_column("activity")) {
        std::set<std::string> ra, sa;
        for (const auto& row : real.rows) ra.insert(row[real.column("activity")]);
        for (const auto& row : synthetic.rows) sa.insert(row[synthetic.column("activity")]);
        for (const std::string& act : ra)
            if (sa.count(act)) {
                const PointMatrix x = columns_of(real, features, act), y = columns_of(synthetic, features, act);
                if (x.rows() >= 5 && y.rows() >= 5) per_activity[act] = test_json(x, y, seed);
            }
    }
    out["per_activity"] = per_activity;
    nlohmann::json distances = nlohmann::json::array();
    for (size_t c = 0; c < features.size(); ++c) {
        const Eigen::VectorXd ca = a.col(static_cast<Eigen::Index>(c)), cb = b.col(static_cast<Eigen::Index>(c));
        const std::vector<double> va(ca.data(), ca.data() + ca.size()), vb(cb.data(), cb.data() + cb.size());
        distances.push_back({{"feature", features[c]}, {"wasserstein_1", wasserstein_1d(va, vb)}, {"ks", ks_statistic(va, vb)}});
    }
    std::stable_sort(distances.begin(), distances.end(), [](const nlohmann::json& x, const nlohmann::json& y) {
        const double kx = x["ks"].is_number() ? x["ks"].get<double>() : -1, ky = y["ks"].is_number() ? y["ks"].get<double>() : -1;
        return kx > ky;
    });
    out["per_feature"] = distances;  // most different first (by KS)
    return out;
}

CsvTable rows_of_activities(const CsvTable& table, const std::vector<std::string>& activities, const std::string& option) {
    const size_t col = table.column("activity");
    CsvTable kept{table.source, table.header, {}};
    std::set<std::string> seen;
    for (const auto& row : table.rows)
        if (std::find(activities.begin(), activities.end(), row[col]) != activities.end()) {
            kept.rows.push_back(row);
            seen.insert(row[col]);
        }
    for (const std::string& a : activities)
        if (!seen.count(a)) throw Error(option, a, "a class " + table.source + " holds windows of");
    return kept;
}

double two_sample_balanced_accuracy(const nlohmann::json& gap, const std::string& path) {
    return json_number(json_object(gap, "classifier_two_sample_test", path), "balanced_accuracy", path, "classifier_two_sample_test");
}

}  // namespace t2imu
