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
            x(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
                v.empty() ? std::nan("") : t.number(rows[r], col);
        }
    }
    return x;
}

TwoSampleSummary two_sample(const PointMatrix& a, const PointMatrix& b, uint64_t seed) {
    const TwoSampleResult r = classifier_two_sample_test(a, b, 5, seed);
    return {r.balanced_accuracy, r.fold_accuracy, a.rows(), b.rows()};
}

nlohmann::json two_sample_json(const TwoSampleSummary& t) {
    return {
        {"balanced_accuracy", t.balanced_accuracy}, {"folds", t.folds}, {"real", t.real}, {"synthetic", t.synthetic}};
}

// A distance JSON wrote as null (NaN: a side held no finite value) reads back as NaN.
double number_or_nan(const nlohmann::json& doc, const char* key, const std::string& path, const std::string& where) {
    if (doc.is_object() && doc.contains(key) && doc[key].is_null()) return std::nan("");
    return json_number(doc, key, path, where);
}

TwoSampleSummary parse_two_sample(const nlohmann::json& doc, const std::string& path, const std::string& where) {
    TwoSampleSummary t;
    t.balanced_accuracy = number_or_nan(doc, "balanced_accuracy", path, where);
    const nlohmann::json& folds = json_array(doc, "folds", path, where);
    for (size_t i = 0; i < folds.size(); ++i) {
        if (!folds[i].is_number() && !folds[i].is_null())
            throw Error(path, where + ".folds." + std::to_string(i), "a number", folds[i].dump());
        t.folds.push_back(folds[i].is_null() ? std::nan("") : folds[i].get<double>());
    }
    t.real = static_cast<int64_t>(json_count(doc, "real", path, where));
    t.synthetic = static_cast<int64_t>(json_count(doc, "synthetic", path, where));
    return t;
}

// Most different first by KS; a NaN distance (no finite values) last.
double ks_rank(double ks) { return std::isnan(ks) ? -1 : ks; }

}  // namespace

DomainGap domain_gap(const CsvTable& real, const CsvTable& synthetic, uint64_t seed) {
    std::vector<std::string> features;
    for (const std::string& h : real.header)
        if (!kLabelColumns.count(h) &&
            std::find(synthetic.header.begin(), synthetic.header.end(), h) != synthetic.header.end())
            features.push_back(h);
    if (features.empty()) throw Error(real.source, "columns", "feature columns shared with " + synthetic.source);
    const PointMatrix a = columns_of(real, features, ""), b = columns_of(synthetic, features, "");
    for (const auto& [table, x] : {std::pair<const CsvTable*, const PointMatrix*>{&real, &a}, {&synthetic, &b}})
        if (x->rows() < 5)
            throw Error(table->source, "windows", "at least 5 (one per fold of the two-sample test)",
                        std::to_string(x->rows()));
    DomainGap gap;
    gap.features = static_cast<int64_t>(features.size());
    gap.overall = two_sample(a, b, seed);
    if (real.has_column("activity") && synthetic.has_column("activity")) {
        std::set<std::string> ra, sa;
        for (const auto& row : real.rows) ra.insert(row[real.column("activity")]);
        for (const auto& row : synthetic.rows) sa.insert(row[synthetic.column("activity")]);
        for (const std::string& act : ra)
            if (sa.count(act)) {
                const PointMatrix x = columns_of(real, features, act), y = columns_of(synthetic, features, act);
                if (x.rows() >= 5 && y.rows() >= 5) gap.per_activity[act] = two_sample(x, y, seed);
            }
    }
    for (size_t c = 0; c < features.size(); ++c) {
        const Eigen::VectorXd ca = a.col(static_cast<Eigen::Index>(c)), cb = b.col(static_cast<Eigen::Index>(c));
        const std::vector<double> va(ca.data(), ca.data() + ca.size()), vb(cb.data(), cb.data() + cb.size());
        gap.per_feature.push_back({features[c], wasserstein_1d(va, vb), ks_statistic(va, vb)});
    }
    std::stable_sort(gap.per_feature.begin(), gap.per_feature.end(),
                     [](const FeatureDistance& x, const FeatureDistance& y) { return ks_rank(x.ks) > ks_rank(y.ks); });
    return gap;
}

nlohmann::json domain_gap_json(const DomainGap& gap) {
    nlohmann::json out;
    out["features"] = gap.features;
    out["classifier_two_sample_test"] = two_sample_json(gap.overall);
    out["note"] =
        "balanced accuracy of logistic regression telling real (0) from synthetic (1), 5-fold CV: 0.5 = "
        "indistinguishable";
    nlohmann::json per_activity = nlohmann::json::object();
    for (const auto& [activity, t] : gap.per_activity) per_activity[activity] = two_sample_json(t);
    out["per_activity"] = per_activity;
    nlohmann::json distances = nlohmann::json::array();
    for (const FeatureDistance& d : gap.per_feature)
        distances.push_back({{"feature", d.feature}, {"wasserstein_1", d.wasserstein_1}, {"ks", d.ks}});
    out["per_feature"] = distances;
    return out;
}

DomainGap parse_domain_gap(const nlohmann::json& doc, const std::string& path) {
    DomainGap gap;
    gap.features = static_cast<int64_t>(json_count(doc, "features", path));
    gap.overall =
        parse_two_sample(json_object(doc, "classifier_two_sample_test", path), path, "classifier_two_sample_test");
    for (const auto& [activity, t] : json_object(doc, "per_activity", path).items())
        gap.per_activity[activity] = parse_two_sample(t, path, "per_activity." + activity);
    const nlohmann::json& distances = json_array(doc, "per_feature", path);
    for (size_t i = 0; i < distances.size(); ++i) {
        const std::string where = "per_feature." + std::to_string(i);
        gap.per_feature.push_back({json_string(distances[i], "feature", path, where),
                                   number_or_nan(distances[i], "wasserstein_1", path, where),
                                   number_or_nan(distances[i], "ks", path, where)});
    }
    return gap;
}

DomainGap read_domain_gap(const std::string& path) { return parse_domain_gap(read_json_file(path), path); }

CsvTable rows_of_activities(const CsvTable& table, const std::vector<std::string>& activities,
                            const std::string& option) {
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

}  // namespace t2imu
