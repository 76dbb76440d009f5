// The report: base64, pose strips, signal statistics, figures drawn by gnuplot, and a self-contained HTML page
// from a results folder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "motion/skeleton.hpp"
#include "motion/stair_gait.hpp"
#include "report/html_page.hpp"
#include "report/html_report.hpp"
#include "report/pose_strip.hpp"
#include "report/signal_stats.hpp"
#include "report_fixture.hpp"
#include "test_util.hpp"
#include "walk_fixture.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

TEST(Report, Base64KnownAnswers) {
    const auto b = [](const std::string& s) { return base64(std::vector<uint8_t>(s.begin(), s.end())); };
    EXPECT_EQ(b("Man"), "TWFu");
    EXPECT_EQ(b("Ma"), "TWE=");
    EXPECT_EQ(b("M"), "TQ==");
    EXPECT_EQ(b(""), "");
    EXPECT_EQ(b("any carnal pleasure."), "YW55IGNhcm5hbCBwbGVhc3VyZS4=");
}

namespace {

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
    return n;
}

}  // namespace

TEST(Report, StripFramesSpreadEvenlyOverTheClip) {
    EXPECT_EQ(strip_frames(120, 6), (std::vector<int>{0, 24, 48, 71, 95, 119}));  // k * 119 / 5, rounded
    EXPECT_EQ(strip_frames(3, 6), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(strip_frames(1, 6), (std::vector<int>{0}));
    EXPECT_EQ(strip_frames(50, 1), (std::vector<int>{0}));
}

TEST(Report, PoseStripDrawsTheKinematicTreeSideOn) {
    // Joint j at height 0.05 j m and 0.02 j m ahead of the pelvis (+Z), the pelvis advancing 0.1 m a frame; the
    // last frame lifted 0.3 m (a jump). x = panel * 200 + 100 + 100 * (z - z_pelvis), y = 220 - 100 * y (cm).
    JointSequence s(21, smpl22::kNumJoints, 20.0);
    for (int f = 0; f < 21; ++f)
        for (int j = 0; j < smpl22::kNumJoints; ++j)
            s.at(f, j) = Eigen::Vector3d(0.01 * j, 0.05 * j + (f == 20 ? 0.3 : 0), 0.02 * j + 0.1 * f);
    const std::string svg = pose_strip_svg(s, 3);  // frames 0, 10, 20: 0.0, 0.5, 1.0 s
    EXPECT_EQ(svg.rfind("<svg class=\"pose-strip\"", 0), 0u);
    EXPECT_NE(svg.find("viewBox=\"0 0 600.0 250.0\" width=\"450.0\" height=\"187.5\""), std::string::npos)
        << svg.substr(0, 200);
    EXPECT_EQ(count(svg, "<line "), 3u * 22u);  // 21 bones and the floor per pose
    // left elbow (18) -> left wrist (20), first pose: left side blue
    EXPECT_NE(svg.find("<line x1=\"136.0\" y1=\"130.0\" x2=\"140.0\" y2=\"120.0\" stroke=\"#3b75af\"/>"),
              std::string::npos);
    // right knee (5) -> right ankle (8), second pose: right side orange
    EXPECT_NE(svg.find("<line x1=\"310.0\" y1=\"195.0\" x2=\"316.0\" y2=\"180.0\" stroke=\"#e08a2c\"/>"),
              std::string::npos);
    // neck (12) -> head (15), third pose, 0.3 m up: centre grey
    EXPECT_NE(svg.find("<line x1=\"524.0\" y1=\"130.0\" x2=\"530.0\" y2=\"115.0\" stroke=\"#555\"/>"),
              std::string::npos);
    for (const char* label : {">0.0 s<", ">0.5 s<", ">1.0 s<"}) EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(Report, PoseStripStandsAClimbOnItsTreads) {
    // A 0.17 m-riser ascent: every pose's lowest joint is drawn just above its panel's ground line (y = 220 cm)
    // rather than a riser higher per step, and the raised panels say how high their ground is.
    StairOptions o = default_stair_options(true);
    o.rise_m = 0.17;
    const StairMotion s = derive_stairs(test::procedural_walk(6.0), o);
    const std::string svg = pose_strip_svg(s.motion, 6);
    EXPECT_GE(count(svg, ", ground +"), 3u);
    const std::regex bone(
        "<line x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\" "
        "stroke=\"#(3b75af|e08a2c|555)\"/>");
    std::vector<double> lowest(6, -1e9);  // the largest y (cm, down) drawn in each panel
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), bone); it != std::sregex_iterator(); ++it) {
        const size_t panel = static_cast<size_t>(std::stod((*it)[1]) / kPanelWidthCm);
        ASSERT_LT(panel, lowest.size());
        lowest[panel] = std::max({lowest[panel], std::stod((*it)[2]), std::stod((*it)[4])});
    }
    for (size_t k = 0; k < lowest.size(); ++k)
        EXPECT_NEAR(lowest[k], kHeadroomCm - 100 * test::kToeHeight, 6.0) << "panel " << k;
}

TEST(Report, SignalStatsKnownAnswers) {
    // |acc| = 9.81 + 2 sin(2 pi 4 t) over 4 s at 64 Hz: sd 2 / sqrt(2), 4 Hz exactly on bin 16 of 256.
    const SignalStats a = signal_stats(test::sine_recording("a.csv", "walking", "waist", 2, 4));
    EXPECT_NEAR(a.acc_sd_m_s2, std::sqrt(2.0), 1e-9);
    EXPECT_DOUBLE_EQ(a.dominant_hz, 4.0);
    // 200 samples at 50 Hz, zero-padded to 256: the nearest bin to 2.5 Hz, 50 / 256 Hz apart.
    const SignalStats b = signal_stats(test::sine_recording("b.csv", "walking", "waist", 1, 2.5, 50, 4));
    EXPECT_NEAR(b.dominant_hz, 2.5, 50.0 / 256 / 2);
    EXPECT_THROW(signal_stats(test::sine_recording("c.csv", "walking", "waist", 1, 1, 50, 0.02)), Error);  // one sample

    const std::vector<SignalStats> s = {{1, 10}, {3, 30}, {2, 20}};
    EXPECT_DOUBLE_EQ(median_of(s, &SignalStats::acc_sd_m_s2), 2);
    EXPECT_DOUBLE_EQ(median_of({{1, 10}, {4, 40}}, &SignalStats::dominant_hz), 25);
    EXPECT_TRUE(std::isnan(median_of({}, &SignalStats::dominant_hz)));
}

TEST(Report, ComparesAtTheCommonPositionPerCanonicalActivity) {
    const auto rec = [](const std::string& activity, const std::string& position, double amplitude) {
        return test::sine_recording(activity + position, activity, position, amplitude, 2);
    };
    const std::vector<ImuRecording> synthetic = {rec("walking", "chest", 1), rec("walking", "chest", 1),
                                                 rec("jogging", "chest", 1), rec("walking", "waist", 1),
                                                 rec("running", "waist", 3)};
    EXPECT_EQ(comparison_position(synthetic, {}), "chest");                            // the most synthetic recordings
    EXPECT_EQ(comparison_position(synthetic, {rec("walking", "waist", 1)}), "waist");  // the real data's
    EXPECT_EQ(comparison_position(synthetic, {rec("walking", "ankle", 1)}), "chest");  // none shared
    EXPECT_EQ(comparison_position({}, {}), "");
    const std::vector<ActivityStats> g = stats_by_activity(
        synthetic, {rec("jogging", "waist", 2), rec("walking", "chest", 2), rec("applauding", "waist", 2)}, "waist");
    ASSERT_EQ(g.size(), 2u);  // running (jogging is running), walking; applauding has no synthetic recordings
    EXPECT_EQ(g[0].activity, "running");
    EXPECT_EQ(g[0].synthetic.size(), 1u);
    ASSERT_EQ(g[0].real.size(), 1u);
    EXPECT_NEAR(g[0].real[0].acc_sd_m_s2, std::sqrt(2.0), 1e-9);
    EXPECT_EQ(g[1].activity, "walking");
    EXPECT_EQ(g[1].synthetic.size(), 1u);
    EXPECT_TRUE(g[1].real.empty());  // the real walking is at the chest
}

TEST(Report, DrawsEveryRecognisedResultIntoOnePage) {
    if (std::system("gnuplot --version > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("report");
    const std::string in = dir + "/results";
    fs::create_directories(in + "/imu");
    write_file_atomic(
        in + "/synthetic_to_real.json",  // har/har_result.hpp's layout; the report reads the run records
        R"({"classes":["running","walking"],"run_records":[)"
        R"({"name":"seed 0","balanced_accuracy":0.55,"macro_f1":0.54,"epochs":5,"seconds_per_epoch":1,"confusion":[[15,5],[7,13]]},)"
        R"({"name":"seed 1","balanced_accuracy":0.65,"macro_f1":0.62,"epochs":6,"seconds_per_epoch":1,"confusion":[[15,5],[7,13]]}]})");
    write_file_atomic(
        in + "/lacc_change.csv",
        "group,samples,l_acc_before,l_acc_after,change_percent\nRunning,10,2,1.6,-20\n"
        "Stair climbing,4,1,0.95,-5\nhigh_dynamic,10,2,1.6,-20\nlow_dynamic,4,1,0.95,-5\nall,14,1.7,1.41,-17.06\n");
    std::string tsne = "source,activity,tsne_x,tsne_y\n";
    for (int i = 0; i < 40; ++i)
        tsne += std::string(i % 2 ? "real" : "synthetic") + "," + (i % 4 < 2 ? "running" : "walking") + "," +
                std::to_string(i) + "," + std::to_string(i % 7) + "\n";
    write_file_atomic(in + "/tsne.csv", tsne);
    std::string trace = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
    for (int k = 0; k < 100; ++k)
        trace += std::to_string(k / 50.0) + ",0.1,9.81," + std::to_string(std::sin(k / 5.0)) + ",0,0.2,0\n";
    write_file_atomic(in + "/imu/chest.csv", trace);
    write_file_atomic(in + "/notes.json", "not json");  // ignored
    write_file_atomic(
        in + "/synth/synth_report.json",
        R"({"jobs":10,"jobs_done":10,"motions_kept":9,"motions_dropped":1,"jobs_regenerated":2,"recordings":63,"failed_attempts_by_score":{},"quality_median":{},)"
        R"("per_activity":{"walking":{"kept":9,"kept_below_activity_agreement":2,"dropped":1}},)"
        R"("this_run":{"jobs_run":10,"total_s":7.5,"motion_generation_s":6.0,"bodies_imu_write_s":1.2,"device":"cpu"}})");
    const auto r = test::run_cli("report --in " + in + " --out " + dir + "/report");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // balanced accuracy + confusion + L_acc + t-SNE (all, high-dynamic) + one trace.
    EXPECT_NE(r.output.find("6 figures"), std::string::npos) << r.output;
    const std::string html = read_file_text(dir + "/report/index.html");
    size_t images = 0;
    for (size_t p = html.find("data:image/png;base64,iVBORw0KGgo"); p != std::string::npos;
         p = html.find("data:image/png;base64,iVBORw0KGgo", p + 1))
        ++images;
    EXPECT_EQ(images, 6u);  // every figure embedded, each a PNG (its signature in base64)
    EXPECT_NE(html.find("60.0 &plusmn; 7.1"), std::string::npos);  // mean and sd (n - 1) of 0.55 and 0.65
    EXPECT_NE(html.find("Synthesis: synth"), std::string::npos);
    EXPECT_NE(html.find("<td>walking</td><td>9</td><td>2</td><td>1</td>"), std::string::npos);
    EXPECT_NE(html.find("10 jobs in 7.5 s"), std::string::npos);
    for (const char* png : {"balanced_accuracy.png", "confusion_synthetic_to_real.png", "lacc_lacc_change.png",
                            "tsne_tsne.png", "tsne_high_tsne.png", "trace_0.png"}) {
        const std::vector<uint8_t> bytes = read_file_bytes(dir + "/report/" + png);
        ASSERT_GT(bytes.size(), 1000u) << png;
        EXPECT_EQ(bytes[1], 'P') << png;
    }
}

TEST(Report, SynthesisFolderShowsEveryKeptMotion) {
    if (std::system("gnuplot --version > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("report_synthesis"), in = dir + "/main-job", real = dir + "/real";
    test::write_synth_fixture(in);
    test::write_real_fixture(real);
    const auto r = test::run_cli("report --in " + in + " --out " + in + "/report --real " + real);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string html = read_file_text(in + "/report/index.html");
    EXPECT_NE(html.find("<h2>Synthesis: main-job</h2>"), std::string::npos);  // the folder's name, not "."
    EXPECT_EQ(count(html, "<svg class=\"pose-strip\""), 2u);                  // one per kept motion
    EXPECT_NE(html.find("&ldquo;a person walks forward briskly&rdquo;"), std::string::npos);
    EXPECT_EQ(html.find("a person strolls"), std::string::npos);  // dropped
    EXPECT_NE(
        html.find(
            "quality: passed (draw 1 of 1)</span> &middot; activity check: shows walking, agreement 0.83, passed"),
        std::string::npos);
    EXPECT_NE(html.find("quality: passed (draw 2 of 2)</span> &middot; activity check: shows walking, agreement 0.40, "
                        "below the minimum"),
              std::string::npos);
    EXPECT_NE(html.find("<a class=\"bvh\" href=\"../motions/j00000.bvh\">j00000.bvh</a>"), std::string::npos);
    EXPECT_NE(html.find("<a class=\"bvh\" href=\"../motions/j00001.bvh\">j00001.bvh</a>"), std::string::npos);
    // Medians at the waist (rounded as written, 4 decimals): walking sd (0.71 + 2.12) / 2 at 2 Hz, real 1.41 at
    // 1.75 Hz; running 4 / sqrt(2) at 3 Hz, no real running.
    EXPECT_NE(html.find("<h3>Signal statistics at the waist</h3>"), std::string::npos);
    EXPECT_NE(html.find("<tr><td>running</td><td>1</td><td>2.83</td><td>3.00</td><td>0</td><td>-</td><td>-</td></tr>"),
              std::string::npos);
    EXPECT_NE(
        html.find("<tr><td>walking</td><td>2</td><td>1.41</td><td>2.00</td><td>1</td><td>1.41</td><td>1.75</td></tr>"),
        std::string::npos);
    const std::vector<uint8_t> png = read_file_bytes(in + "/report/signal_stats_0.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png[1], 'P');
}
