// The report: base64, figures drawn by gnuplot, and a self-contained HTML page from a results folder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.hpp"
#include "report/html_report.hpp"
#include "test_util.hpp"

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

TEST(Report, DrawsEveryRecognisedResultIntoOnePage) {
    if (std::system("gnuplot --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("report");
    const std::string in = dir + "/results";
    fs::create_directories(in + "/imu");
    write_file_atomic(in + "/synthetic_to_real.json",
                      R"({"classes":["running","walking"],"balanced_accuracy":{"mean":0.6,"sd":0.05,"runs":[0.55,0.65]},)"
                      R"("macro_f1":{"mean":0.58,"sd":0.04,"runs":[0.54,0.62]},"confusion":[[30,10],[14,26]]})");
    write_file_atomic(in + "/lacc_change.csv", "group,samples,l_acc_before,l_acc_after,change_percent\nRunning,10,2,1.6,-20\n"
                                               "Stair climbing,4,1,0.95,-5\nhigh_dynamic,10,2,1.6,-20\nlow_dynamic,4,1,0.95,-5\nall,14,1.7,1.41,-17.06\n");
    std::string tsne = "source,activity,tsne_x,tsne_y\n";
    for (int i = 0; i < 40; ++i) tsne += std::string(i % 2 ? "real" : "synthetic") + "," + (i % 4 < 2 ? "running" : "walking") + "," + std::to_string(i) + "," + std::to_string(i % 7) + "\n";
    write_file_atomic(in + "/tsne.csv", tsne);
    std::string trace = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
    for (int k = 0; k < 100; ++k) trace += std::to_string(k / 50.0) + ",0.1,9.81," + std::to_string(std::sin(k / 5.0)) + ",0,0.2,0\n";
    write_file_atomic(in + "/imu/chest.csv", trace);
    write_file_atomic(in + "/notes.json", "not json");  // ignored
    write_file_atomic(in + "/synth/synth_report.json",
                      R"({"jobs":10,"jobs_done":10,"motions_kept":9,"jobs_regenerated":2,"recordings":63,)"
                      R"("per_activity":{"walking":{"kept":9,"kept_below_activity_agreement":2,"dropped":1}},)"
                      R"("this_run":{"jobs_run":10,"total_s":7.5,"motion_generation_s":6.0,"bodies_imu_write_s":1.2,"device":"cpu"}})");
    const auto r = test::run_cli("report --in " + in + " --out " + dir + "/report");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // balanced accuracy + confusion + L_acc + t-SNE (all, high-dynamic) + one trace.
    EXPECT_NE(r.output.find("6 figures"), std::string::npos) << r.output;
    const std::string html = read_file_text(dir + "/report/index.html");
    size_t images = 0;
    for (size_t p = html.find("data:image/png;base64,iVBORw0KGgo"); p != std::string::npos; p = html.find("data:image/png;base64,iVBORw0KGgo", p + 1)) ++images;
    EXPECT_EQ(images, 6u);  // every figure embedded, each a PNG (its signature in base64)
    EXPECT_NE(html.find("60.0 &plusmn; 5.0"), std::string::npos);
    EXPECT_NE(html.find("Synthesis: synth"), std::string::npos);
    EXPECT_NE(html.find("<td>walking</td><td>9</td><td>2</td><td>1</td>"), std::string::npos);
    EXPECT_NE(html.find("10 jobs in 7.5 s"), std::string::npos);
    for (const char* png : {"balanced_accuracy.png", "confusion_synthetic_to_real.png", "lacc_lacc_change.png", "tsne_tsne.png", "tsne_high_tsne.png", "trace_0.png"}) {
        const std::vector<uint8_t> bytes = read_file_bytes(dir + "/report/" + png);
        ASSERT_GT(bytes.size(), 1000u) << png;
        EXPECT_EQ(bytes[1], 'P') << png;
    }
}
