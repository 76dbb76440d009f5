// Real-vs-synthetic distances: the classifier two-sample test and per-feature distribution distances.
#include <gtest/gtest.h>

#include <random>

#include "analysis/domain_gap.hpp"
#include "analysis/two_sample.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {
PointMatrix gaussian(int n, int d, double shift, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    PointMatrix x(n, d);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < d; ++j) x(i, j) = g(rng) + (j == 0 ? shift : 0.0);
    return x;
}
}  // namespace

TEST(TwoSample, SameDistributionIsIndistinguishableShiftedIsNot) {
    const TwoSampleResult same = classifier_two_sample_test(gaussian(400, 10, 0, 1), gaussian(300, 10, 0, 2));
    EXPECT_NEAR(same.balanced_accuracy, 0.5, 0.06);
    EXPECT_EQ(same.fold_accuracy.size(), 5u);
    // A 3-sigma shift in one feature: Bayes-optimal balanced accuracy Phi(1.5) = 0.933.
    const TwoSampleResult apart = classifier_two_sample_test(gaussian(400, 10, 0, 3), gaussian(300, 10, 3, 4));
    EXPECT_NEAR(apart.balanced_accuracy, 0.933, 0.03);
    // NaN columns (a constant channel's catch22) are dropped, not fatal.
    PointMatrix with_nan = gaussian(300, 10, 3, 5);
    with_nan.col(4).setConstant(std::nan(""));
    EXPECT_NEAR(classifier_two_sample_test(gaussian(400, 10, 0, 6), with_nan).balanced_accuracy, 0.933, 0.03);
    EXPECT_THROW(classifier_two_sample_test(gaussian(10, 3, 0, 1), gaussian(10, 4, 0, 1)), Error);
}

TEST(TwoSample, WassersteinAndKolmogorovSmirnovKnownAnswers) {
    // W1 of two point sets of equal size = mean |sorted a - sorted b|: (|0-1| + |1-3| + |5-5|) / 3 = 1.
    EXPECT_NEAR(wasserstein_1d({5, 0, 1}, {3, 1, 5}), 1.0, 1e-12);
    EXPECT_NEAR(wasserstein_1d({0, 0}, {2, 2, 2}), 2.0, 1e-12);  // a shift of 2
    EXPECT_DOUBLE_EQ(ks_statistic({1, 2, 3}, {1, 2, 3}), 0.0);
    EXPECT_DOUBLE_EQ(ks_statistic({1, 2}, {3, 4}), 1.0);
    EXPECT_DOUBLE_EQ(ks_statistic({1, 2, 3, 4}, {3, 4, 5, 6}), 0.5);
    EXPECT_DOUBLE_EQ(wasserstein_1d({1, std::nan(""), 2}, {1, 2}), 0.0);  // NaN dropped
}

TEST(TwoSample, ADomainGapResultReadsBackAsWrittenToTheByte) {
    DomainGap gap;
    gap.features = 3;
    gap.overall = {0.75, {0.7, 0.8}, 120, 80};
    gap.per_activity["walking"] = {0.625, {0.5, 0.75}, 60, 40};
    gap.per_feature = {{"f2", 0.5, 0.25}, {"f1", 0.125, std::nan("")}};  // a NaN distance: JSON null
    const nlohmann::json doc = domain_gap_json(gap);
    EXPECT_TRUE(nlohmann::json::parse(doc.dump())["per_feature"][1]["ks"].is_null());
    EXPECT_EQ(doc["classifier_two_sample_test"]["real"], 120);
    const std::string file = test::scratch_dir("domain_gap") + "/gap.json";
    write_file_atomic(file, doc.dump(2) + "\n");
    const DomainGap back = read_domain_gap(file);
    EXPECT_EQ(back.overall.folds, gap.overall.folds);
    EXPECT_EQ(back.per_activity.at("walking").real, 60);
    EXPECT_TRUE(std::isnan(back.per_feature[1].ks));
    EXPECT_EQ(domain_gap_json(back).dump(2), doc.dump(2));
    nlohmann::json broken = doc;
    broken["per_feature"][0]["ks"] = "far";
    EXPECT_EQ(test::error_message([&] { parse_domain_gap(broken, "g.json"); }),
              "g.json: per_feature.0.ks: expected a number (got \"far\")");
    broken = doc;
    broken.erase("classifier_two_sample_test");
    EXPECT_THROW(parse_domain_gap(broken, "g.json"), Error);
}

TEST(TwoSample, DomainGapOnFeatureTables) {
    // Two tables with activity labels; "walking" differs between them in f1, "running" does not.
    std::mt19937_64 rng(9);
    std::normal_distribution<double> g;
    const auto table = [&](double walking_shift) {
        CsvTable t;
        t.source = "t";
        t.header = {"subject", "activity", "f1", "f2"};
        for (int i = 0; i < 200; ++i) {
            const bool walking = i % 2 == 0;
            t.rows.push_back({"s", walking ? "walking" : "running",
                              std::to_string(g(rng) + (walking ? walking_shift : 0.0)), std::to_string(g(rng))});
        }
        return t;
    };
    const DomainGap gap = domain_gap(table(0), table(4));
    EXPECT_EQ(gap.features, 2);
    EXPECT_GT(gap.per_activity.at("walking").balanced_accuracy, 0.95);
    EXPECT_NEAR(gap.per_activity.at("running").balanced_accuracy, 0.5, 0.12);
    EXPECT_EQ(gap.per_feature[0].feature, "f1");  // the most different feature first
    EXPECT_GT(gap.per_feature[0].ks, 0.4);
    // Restricted to the class both tables share alike, the pooled test cannot tell them apart either.
    const CsvTable a = rows_of_activities(table(0), {"running"}, "--classes"),
                   b = rows_of_activities(table(4), {"running"}, "--classes");
    EXPECT_EQ(a.rows.size(), 100u);
    EXPECT_GT(gap.overall.balanced_accuracy, 0.65);
    EXPECT_NEAR(domain_gap(a, b).overall.balanced_accuracy, 0.5, 0.12);
    EXPECT_EQ(test::error_message([&] {
                  rows_of_activities(table(0), {"running", "lying"}, "--classes");
              }),
              "--classes: lying: expected a class t holds windows of");
}

// Too few windows for the folds: the error names the set that has too few (it once named neither).
TEST(TwoSample, TooFewWindowsNameTheSet) {
    const auto table = [](const std::string& source, int rows) {
        CsvTable t;
        t.source = source;
        t.header = {"activity", "f1", "f2"};
        for (int r = 0; r < rows; ++r) t.rows.push_back({"walking", std::to_string(r), std::to_string(r * r)});
        return t;
    };
    std::string m = test::error_message([&] { domain_gap(table("real.csv", 3), table("synthetic.csv", 40), 0); });
    EXPECT_TRUE(test::contains(m, "real.csv: windows: expected at least 5") && test::contains(m, "(got 3)")) << m;
    m = test::error_message([&] { domain_gap(table("real.csv", 40), table("synthetic.csv", 4), 0); });
    EXPECT_TRUE(test::contains(m, "synthetic.csv: windows")) << m;
    m = test::error_message([&] { classifier_two_sample_test(PointMatrix::Zero(3, 2), PointMatrix::Zero(9, 2)); });
    EXPECT_TRUE(test::contains(m, "3 real, 9 synthetic")) << m;
}
