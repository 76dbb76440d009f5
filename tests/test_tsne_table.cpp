// tsne_table: which columns are labels and which features, per-column standardisation (missing values and
// constant columns at 0), the embedding table's columns and values, two separated groups staying apart, and
// refused input naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "analysis/tsne_table.hpp"
#include "core/error.hpp"

using namespace t2imu;

namespace {
TsneOptions small_options() {
    TsneOptions o;
    o.perplexity = 4;
    o.exact = true;
    o.theta = 0;
    o.iterations = 400;
    return o;
}

// Two groups of 10 rows, far apart in f1 and f2; a constant column; one missing value; a text column.
CsvTable two_groups() {
    CsvTable t;
    t.header = {"subject", "source", "f1", "f2", "flat", "note"};
    for (int i = 0; i < 20; ++i) {
        const bool b = i >= 10;
        const double jitter = 0.1 * ((i * 7) % 10);
        t.rows.push_back({std::to_string(i % 3), b ? "synthetic" : "real", std::to_string((b ? 10 : 0) + jitter),
                          i == 4 ? "nan" : std::to_string((b ? -5 : 5) + jitter * 0.5), "3.5", i == 0 ? "x y" : "7"});
    }
    return t;
}
}  // namespace

TEST(TsneTable, LabelsAndFeaturesAreSplitAsDocumented) {
    const TsneTable t = tsne_table(two_groups(), {"subject"}, small_options(), "features.csv");
    // subject is numeric but named a label; source and note hold non-numbers; f1, f2, flat are features.
    EXPECT_EQ(t.embedding.header, (std::vector<std::string>{"subject", "source", "note", "tsne_x", "tsne_y"}));
    EXPECT_EQ(t.feature_columns, 3u);
    ASSERT_EQ(t.features.rows(), 20);
    ASSERT_EQ(t.features.cols(), 3);
    EXPECT_EQ(t.embedding.rows[0][2], "x y");
    EXPECT_EQ(t.embedding.rows[13][1], "synthetic");
    // The printed coordinates are the result's (%.6g).
    for (int r = 0; r < 20; ++r)
        for (int d = 0; d < 2; ++d)
            EXPECT_NEAR(std::strtod(t.embedding.rows[r][3 + d].c_str(), nullptr), t.result.embedding(r, d),
                        1e-5 * std::max(1.0, std::fabs(t.result.embedding(r, d))));
}

TEST(TsneTable, ColumnsAreStandardised) {
    const TsneTable t = tsne_table(two_groups(), {"subject"}, small_options(), "features.csv");
    // f1 over its 20 rows: mean 0 and population sd 1 after standardising.
    double sum = 0, sum_sq = 0;
    for (int r = 0; r < 20; ++r) sum += t.features(r, 0), sum_sq += t.features(r, 0) * t.features(r, 0);
    EXPECT_NEAR(sum / 20, 0.0, 1e-12);
    EXPECT_NEAR(sum_sq / 20, 1.0, 1e-12);
    // The missing f2 value sits at the column mean (0); the constant column is all 0.
    EXPECT_DOUBLE_EQ(t.features(4, 1), 0.0);
    for (int r = 0; r < 20; ++r) EXPECT_DOUBLE_EQ(t.features(r, 2), 0.0);
    // A hand-computed column: 1, 2, 3, 6 -> mean 3, population sd sqrt((4 + 1 + 0 + 9) / 4) = sqrt(3.5).
    CsvTable small;
    small.header = {"label", "v"};
    for (const char* v : {"1", "2", "3", "6"}) small.rows.push_back({"a", v});
    TsneOptions o = small_options();
    o.perplexity = 1;
    const TsneTable s = tsne_table(small, {}, o, "small.csv");
    EXPECT_NEAR(s.features(0, 0), -2 / std::sqrt(3.5), 1e-12);
    EXPECT_NEAR(s.features(1, 0), -1 / std::sqrt(3.5), 1e-12);
    EXPECT_NEAR(s.features(2, 0), 0.0, 1e-12);
    EXPECT_NEAR(s.features(3, 0), 3 / std::sqrt(3.5), 1e-12);
}

TEST(TsneTable, SeparatedGroupsStayApart) {
    const TsneTable t = tsne_table(two_groups(), {"subject"}, small_options(), "features.csv");
    // Every point is nearer to the centre of its own group than to the other group's.
    Eigen::Vector2d centre[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    for (int r = 0; r < 20; ++r) centre[r >= 10] += t.result.embedding.row(r).transpose() / 10.0;
    for (int r = 0; r < 20; ++r) {
        const Eigen::Vector2d p = t.result.embedding.row(r).transpose();
        EXPECT_LT((p - centre[r >= 10]).norm(), (p - centre[r < 10]).norm()) << "row " << r;
    }
}

TEST(TsneTable, RefusesTablesWithNothingToEmbed) {
    CsvTable empty;
    empty.header = {"a", "b"};
    try {
        tsne_table(empty, {}, small_options(), "empty.csv");
        ADD_FAILURE() << "no rows accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("empty.csv"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("rows"), std::string::npos) << e.what();
    }
    CsvTable labels_only;
    labels_only.header = {"subject", "activity"};
    labels_only.rows = {{"1", "walking"}, {"2", "running"}};
    try {
        tsne_table(labels_only, {"subject"}, small_options(), "labels.csv");
        ADD_FAILURE() << "no feature columns accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("labels.csv"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("columns"), std::string::npos) << e.what();
    }
}
