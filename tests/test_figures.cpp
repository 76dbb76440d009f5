// The evaluation's figures: each draws a PNG, and the data it hands gnuplot (the script captured through
// $T2IMU_GNUPLOT) holds the hand-computed values: recall-normalised confusion rows, accuracy in percent, L_acc
// bars with a range that holds zero, t-SNE groups filtered by a column, signal-statistics medians either side of
// the tick, IMU trace columns in t, acc, gyr order whatever the CSV's order. Missing columns and nothing to plot
// are refused naming them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "report/figures.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// Captures every script sent to gnuplot into `<dir>/script.gp` while it still draws.
struct Capture {
    std::string dir, script_path;
    explicit Capture(const std::string& name) : dir(test::scratch_dir(name)), script_path(dir + "/script.gp") {
        setenv("T2IMU_GNUPLOT", ("tee '" + script_path + "' | gnuplot").c_str(), 1);
    }
    ~Capture() { unsetenv("T2IMU_GNUPLOT"); }
    std::string script() const { return read_file_text(script_path); }
    bool png(const std::string& name) const {
        const std::vector<uint8_t> b = read_file_bytes(dir + "/" + name);
        return b.size() > 100 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G';
    }
};

CsvTable table(const std::string& text) { return parse_csv(text, "test.csv"); }
}  // namespace

TEST(Figures, ConfusionRowsAreNormalisedToRecall) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_confusion");
    // Rows are true classes: 30 + 10 -> 0.75, 0.25; 14 + 26 -> 0.35, 0.65; an empty row stays 0.
    // Two runs whose confusions sum to the matrix drawn.
    HarResult result;
    result.classes = {"running", "walking", "sitting"};
    result.runs.resize(2);
    result.runs[0].confusion = {{20, 5, 0}, {4, 16, 0}, {0, 0, 0}};
    result.runs[1].confusion = {{10, 5, 0}, {10, 10, 0}, {0, 0, 0}};
    plot_confusion(result, c.dir + "/cm.png", "Confusion");
    EXPECT_TRUE(c.png("cm.png"));
    const std::string s = c.script();
    EXPECT_TRUE(test::contains(
        s, "$cm << EOD\n0 0 0.75\n1 0 0.25\n2 0 0\n\n0 1 0.35\n1 1 0.65\n2 1 0\n\n0 2 0\n1 2 0\n2 2 0\n\nEOD"))
        << s;
    EXPECT_TRUE(test::contains(s, "\"running\" 0, \"walking\" 1, \"sitting\" 2")) << s;
}

TEST(Figures, BalancedAccuracyInPercent) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_accuracy");
    const auto result_of = [](std::vector<double> runs) {
        HarResult r;
        for (double ba : runs) r.runs.emplace_back(), r.runs.back().balanced_accuracy = ba;
        return r;
    };
    // 0.55 and 0.65: mean 60 %, sd (n - 1) 7.07107 %; one run: sd 0.
    plot_balanced_accuracy({{"mdm_acc", result_of({0.55, 0.65})}, {"retrieval", result_of({0.425})}},
                           c.dir + "/ba.png");
    EXPECT_TRUE(c.png("ba.png"));
    EXPECT_TRUE(test::contains(c.script(), "$acc << EOD\n0 \"mdm\\\\_acc\" 60 7.07107\n1 \"retrieval\" 42.5 0\nEOD"))
        << c.script();
}

TEST(Figures, LowDataCurveOneLineAndBandPerArm) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_low_data");
    LowDataCurve curve{"sisfall", {"a", "b"}, {"0", "1", "all"}, {}};
    curve.arms.push_back({"real only", {{"1", 1, {0.6, 0.7}}, {"all", 24, {0.9, 0.9}}}});
    curve.arms.push_back({"mdm mix", {{"0", 0, {0.75}}, {"1", 1, {0.8, 0.8}}}});
    plot_low_data_curve(curve, c.dir + "/ld.png");
    EXPECT_TRUE(c.png("ld.png"));
    const std::string s = c.script();
    // x at the K's place (1 and 2 for real only), mean, mean - sd, mean + sd in percent.
    EXPECT_TRUE(test::contains(s, "$arm0 << EOD\n1 65 57.9289 72.0711\n2 90 90 90\nEOD")) << s;
    EXPECT_TRUE(test::contains(s, "$arm1 << EOD\n0 75 75 75\n1 80 80 80\nEOD")) << s;
    EXPECT_TRUE(test::contains(s, "\"0\" 0, \"1\" 1, \"all\" 2")) << s;
    EXPECT_TRUE(test::contains(s, "title \"real only\"")) << s;
    EXPECT_TRUE(test::contains(test::error_message([&] { plot_low_data_curve(LowDataCurve{}, c.dir + "/x.png"); }),
                               "at least one K"));
}

TEST(Figures, LaccBarsAndARangeThatHoldsZero) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_lacc");
    // Changes -20 and -17.06: the range spans [-20, 0] padded by 10 % of 20: [-22:2]; aggregates coloured 2.
    plot_lacc_change(table("group,samples,change_percent\nRunning,10,-20\nall,14,-17.06\n"), c.dir + "/lacc.png");
    EXPECT_TRUE(c.png("lacc.png"));
    const std::string s = c.script();
    EXPECT_TRUE(test::contains(s, "$bars << EOD\n0 \"Running (10)\" -20 1\n1 \"all (14)\" -17.06 2\nEOD")) << s;
    EXPECT_TRUE(test::contains(s, "set yrange [-22:2]")) << s;
    const std::string m =
        test::error_message([&] { plot_lacc_change(table("group,samples\nRunning,10\n"), c.dir + "/x.png"); });
    EXPECT_TRUE(test::contains(m, "change_percent")) << m;
}

TEST(Figures, TsneGroupsByColourAndFilters) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_tsne");
    const CsvTable t = table(
        "source,activity,tsne_x,tsne_y\nreal,running,1,2\nsynthetic,walking,3,4\nsynthetic,running,5,6\nreal,walking,7,"
        "8\n");
    plot_tsne(t, "source", c.dir + "/tsne.png", "t-SNE", "activity", {"running"});
    EXPECT_TRUE(c.png("tsne.png"));
    const std::string s = c.script();
    // One group per source (alphabetical), only the running rows.
    EXPECT_TRUE(test::contains(s, "$g0 << EOD\n1 2\nEOD\n$g1 << EOD\n5 6\nEOD")) << s;
    EXPECT_TRUE(test::contains(s, "title \"real\"") && test::contains(s, "title \"synthetic\"")) << s;
    std::string m =
        test::error_message([&] { plot_tsne(t, "source", c.dir + "/none.png", "t", "activity", {"lying"}); });
    EXPECT_TRUE(test::contains(m, c.dir + "/none.png") && test::contains(m, "points")) << m;
    m = test::error_message([&] { plot_tsne(t, "body", c.dir + "/nobody.png", "t"); });
    EXPECT_TRUE(test::contains(m, "body")) << m;
}

TEST(Figures, SignalStatsMediansEitherSideOfTheTick) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_stats");
    // Walking: synthetic sd 1 and 3 at 2 Hz (median 2, 2), real sd 2 at 1.75 Hz; with real data synthetic sits at
    // x = i - 0.2 and real at i + 0.2. Running: synthetic only.
    std::vector<ActivityStats> groups = {{"running", {{4, 3}}, {}}, {"walking", {{1, 2}, {3, 2}}, {{2, 1.75}}}};
    plot_signal_stats(groups, c.dir + "/stats.png", "Signal statistics");
    EXPECT_TRUE(c.png("stats.png"));
    const std::string s = c.script();
    EXPECT_TRUE(test::contains(s, "$msyn << EOD\n-0.2 4 3\n0.8 2 2\nEOD")) << s;
    EXPECT_TRUE(test::contains(s, "$mreal << EOD\n1.2 2 1.75\nEOD")) << s;
    // Without real data the synthetic medians sit on the ticks and no real series is drawn.
    groups[1].real.clear();
    plot_signal_stats(groups, c.dir + "/alone.png", "Signal statistics");
    EXPECT_TRUE(test::contains(c.script(), "$msyn << EOD\n0 4 3\n1 2 2\nEOD")) << c.script();
    EXPECT_FALSE(test::contains(c.script(), "$mreal"));
    const std::string m = test::error_message([&] { plot_signal_stats({}, c.dir + "/empty.png", "x"); });
    EXPECT_TRUE(test::contains(m, c.dir + "/empty.png") && test::contains(m, "activities")) << m;
}

TEST(Figures, ImuTraceColumnsInOrder) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const Capture c("figures_trace");
    // The CSV's columns in another order: the data block is t, acc x y z, gyr x y z.
    plot_imu_trace(table("gyr_z,gyr_y,gyr_x,acc_z,acc_y,acc_x,t\n6,5,4,3,2,1,0\n16,15,14,13,12,11,0.02\n"),
                   c.dir + "/trace.png", "trace");
    EXPECT_TRUE(c.png("trace.png"));
    EXPECT_TRUE(test::contains(c.script(), "$imu << EOD\n0 1 2 3 4 5 6\n0.02 11 12 13 14 15 16\nEOD")) << c.script();
    const std::string m = test::error_message(
        [&] { plot_imu_trace(table("t,acc_x,acc_y,acc_z,gyr_x,gyr_y\n0,1,2,3,4,5\n"), c.dir + "/x.png", "t"); });
    EXPECT_TRUE(test::contains(m, "gyr_z")) << m;
}
