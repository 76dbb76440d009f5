// t-SNE on data with known cluster structure, and trustworthiness against hand-checkable cases.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "analysis/tsne.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

// `clusters` Gaussian blobs of `per` points in `dims` dimensions, centres 10 apart, unit spread.
PointMatrix blobs(int clusters, int per, int dims, std::vector<int>* label, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n;
    PointMatrix x(clusters * per, dims);
    for (int c = 0; c < clusters; ++c) {
        Eigen::RowVectorXd centre(dims);
        for (int d = 0; d < dims; ++d) centre[d] = 10 * n(rng);
        for (int i = 0; i < per; ++i) {
            for (int d = 0; d < dims; ++d) x(c * per + i, d) = centre[d] + n(rng);
            label->push_back(c);
        }
    }
    return x;
}

// Share of points whose 5 nearest embedded neighbours mostly carry their own label.
double knn_label_agreement(const PointMatrix& y, const std::vector<int>& label) {
    int good = 0;
    for (Eigen::Index i = 0; i < y.rows(); ++i) {
        std::vector<std::pair<double, int>> d;
        for (Eigen::Index j = 0; j < y.rows(); ++j)
            if (j != i) d.push_back({(y.row(i) - y.row(j)).squaredNorm(), label[static_cast<size_t>(j)]});
        std::partial_sort(d.begin(), d.begin() + 5, d.end());
        int same = 0;
        for (int k = 0; k < 5; ++k) same += d[static_cast<size_t>(k)].second == label[static_cast<size_t>(i)];
        good += same >= 3;
    }
    return static_cast<double>(good) / static_cast<double>(y.rows());
}

}  // namespace

TEST(Trustworthiness, OneForAnIsometryAndLowerForAShuffle) {
    std::vector<int> label;
    const PointMatrix x = blobs(3, 30, 2, &label, 1);
    const Eigen::Matrix2d rot = Eigen::Rotation2Dd(0.7).toRotationMatrix();
    const PointMatrix turned = x * rot.transpose() * 3.0;  // rotation and scale keep every neighbourhood
    EXPECT_DOUBLE_EQ(trustworthiness(x, turned, 5), 1.0);
    PointMatrix shuffled = x;
    std::mt19937_64 rng(2);
    for (Eigen::Index i = shuffled.rows() - 1; i > 0; --i)
        shuffled.row(i).swap(shuffled.row(std::uniform_int_distribution<Eigen::Index>(0, i)(rng)));
    EXPECT_LT(trustworthiness(x, shuffled, 5), 0.7);
    EXPECT_THROW(trustworthiness(x, turned.topRows(10), 5), Error);
}

TEST(Tsne, SeparatesGaussianBlobsExactAndBarnesHut) {
    std::vector<int> label;
    const PointMatrix x = blobs(4, 60, 20, &label, 3);
    TsneOptions exact;
    exact.exact = true;
    const TsneResult e = tsne(x, exact);
    const TsneResult b = tsne(x, {});
    for (const TsneResult* r : {&e, &b}) {
        EXPECT_GT(knn_label_agreement(r->embedding, label), 0.99);
        EXPECT_GT(trustworthiness(x, r->embedding, 5), 0.9);
        EXPECT_TRUE(r->embedding.allFinite());
    }
    EXPECT_LT(e.kl_divergence, 1.5);
    EXPECT_NEAR(b.kl_divergence, e.kl_divergence, 0.25);  // the approximation costs little on 240 points
}

TEST(Tsne, IsDeterministicAndRefusesBadInput) {
    std::vector<int> label;
    const PointMatrix x = blobs(2, 20, 5, &label, 4);
    TsneOptions o;
    o.perplexity = 5;
    o.iterations = 300;
    EXPECT_EQ(tsne(x, o).embedding, tsne(x, o).embedding);
    o.perplexity = 30;  // needs more than 90 points
    EXPECT_THROW(tsne(x, o), Error);
    PointMatrix bad = x;
    bad(3, 2) = std::nan("");
    EXPECT_THROW(tsne(bad, {}), Error);
}

TEST(Tsne, CliEmbedsAFeatureTableAndCarriesLabels) {
    std::vector<int> label;
    const PointMatrix x = blobs(3, 40, 6, &label, 5);
    const std::string dir = test::scratch_dir("tsne_cli");
    CsvTable t;
    // "window" is numeric but a label of catch22 tables, not a feature; a "nan" feature (catch22 of a flat
    // channel) must not take its row out.
    t.header = {"label", "window", "f1", "f2", "f3", "f4", "f5", "f6"};
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
        std::vector<std::string> row = {"c" + std::to_string(label[static_cast<size_t>(i)]), std::to_string(i * 1000)};
        for (Eigen::Index d = 0; d < 6; ++d) row.push_back(std::to_string(x(i, d)));
        t.rows.push_back(row);
    }
    t.rows[7][4] = "nan";
    write_csv(dir + "/x.csv", t);
    const auto r = test::run_cli("tsne --in " + dir + "/x.csv --out " + dir + "/y.csv --perplexity 10");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("trustworthiness"), std::string::npos);
    const CsvTable y = read_csv(dir + "/y.csv");
    EXPECT_EQ(y.header, (std::vector<std::string>{"label", "window", "tsne_x", "tsne_y"}));
    ASSERT_EQ(y.rows.size(), 120u);
    EXPECT_EQ(y.rows[5][1], "5000");
    PointMatrix e(120, 2);
    for (size_t i = 0; i < 120; ++i) e.row(static_cast<Eigen::Index>(i)) << y.number(i, 2), y.number(i, 3);
    EXPECT_GT(knn_label_agreement(e, label), 0.99);
}

TEST(Tsne, OptionsNoDataCouldMakeValidAreRefusedNamingTheOption) {
    EXPECT_NO_THROW(TsneOptions{}.validate());
    const auto refusal = [](auto change) {
        TsneOptions o;
        change(o);
        return test::error_message([&] { o.validate(); });
    };
    EXPECT_NE(refusal([](TsneOptions& o) { o.perplexity = std::nan(""); }).find("--perplexity"), std::string::npos);
    EXPECT_NE(refusal([](TsneOptions& o) { o.perplexity = 0; }).find("--perplexity"), std::string::npos);
    EXPECT_NE(refusal([](TsneOptions& o) { o.perplexity = 1e12; }).find("--perplexity"), std::string::npos);
    EXPECT_NE(refusal([](TsneOptions& o) { o.iterations = 0; }).find("--iterations"), std::string::npos);
    EXPECT_NE(refusal([](TsneOptions& o) { o.iterations = 100; }).find("exaggeration"),
              std::string::npos);  // 250 > 100
}
