// har/low_data_curve: the curve's JSON written and read back, a point made from a result of draws, and damaged files
// refused naming the key.
#include "har/low_data_curve.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

LowDataCurve curve() {
    LowDataCurve c{"sisfall", {"lying", "walking"}, {"0", "1", "all"}, {}};
    c.arms.push_back({"real only", {{"1", 1, {0.6, 0.7}}, {"all", 24, {0.9, 0.92}}}});
    c.arms.push_back({"mdm mix", {{"0", 0, {0.75}}, {"1", 1, {0.8, 0.82}}, {"all", 24, {0.91, 0.9}}}});
    return c;
}

}  // namespace

TEST(LowDataCurve, RoundTripAndSummaries) {
    const nlohmann::json j = low_data_curves_json({curve()});
    EXPECT_TRUE(is_low_data_curves(j));
    EXPECT_NEAR(j["low_data_curves"][0]["arms"][0]["points"][0]["mean"].get<double>(), 0.65, 1e-12);
    EXPECT_NEAR(j["low_data_curves"][0]["arms"][0]["points"][0]["sd"].get<double>(), 0.0707107, 1e-6);  // sd (n - 1)
    const std::vector<LowDataCurve> back = parse_low_data_curves(j, "curves.json");
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].labels, curve().labels);
    EXPECT_EQ(back[0].classes, curve().classes);
    ASSERT_EQ(back[0].arms.size(), 2u);
    EXPECT_EQ(back[0].arms[1].name, "mdm mix");
    ASSERT_NE(back[0].arms[1].at("all"), nullptr);
    EXPECT_EQ(back[0].arms[1].at("all")->train_subjects, 24);
    EXPECT_EQ(back[0].arms[1].at("all")->draws, (std::vector<double>{0.91, 0.9}));
    EXPECT_EQ(back[0].arms[0].at("0"), nullptr);  // real only has no K = 0
}

TEST(LowDataCurve, PointFromDraws) {
    HarResult r;
    r.classes = {"a", "b"};
    for (double ba : {0.5, 0.7, 0.6}) {
        HarRun run;
        run.balanced_accuracy = ba;
        run.train_subjects = {"SA01", "SA07"};
        r.runs.push_back(run);
    }
    const LowDataPoint p = low_data_point(r, "2");
    EXPECT_EQ(p.label, "2");
    EXPECT_EQ(p.train_subjects, 2);
    EXPECT_EQ(p.draws, (std::vector<double>{0.5, 0.7, 0.6}));
    EXPECT_NEAR(p.balanced_accuracy().mean, 0.6, 1e-12);
    EXPECT_NEAR(p.balanced_accuracy().sd, 0.1, 1e-12);
}

TEST(LowDataCurve, DamagedNamesTheKey) {
    nlohmann::json j = low_data_curves_json({curve()});
    j["low_data_curves"][0]["arms"][1]["points"][2]["draws"][0] = "high";
    EXPECT_TRUE(test::contains(test::error_message([&] { parse_low_data_curves(j, "c.json"); }),
                               "c.json: low_data_curves.0.arms.1.points.2.draws"));
    j = low_data_curves_json({curve()});
    j["low_data_curves"][0].erase("labels");
    EXPECT_TRUE(test::contains(test::error_message([&] { parse_low_data_curves(j, "c.json"); }),
                               "c.json: low_data_curves.0.labels"));
}
