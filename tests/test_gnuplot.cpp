// gnuplot rendering: labels quoted with enhanced-text characters escaped; a PNG of the requested size (read from
// its IHDR chunk); data blocks sent as inline heredocs (the script captured through $T2IMU_GNUPLOT); a failing
// script or program refused naming the PNG, with nothing left behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "report/gnuplot.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23), after checking the signature.
std::pair<uint32_t, uint32_t> png_size(const std::string& path) {
    const std::vector<uint8_t> b = read_file_bytes(path);
    const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (b.size() < 24 || !std::equal(signature, signature + 8, b.begin())) return {0, 0};
    auto be32 = [&](size_t at) {
        return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 | uint32_t(b[at + 3]);
    };
    return {be32(16), be32(20)};
}

// Sets $T2IMU_GNUPLOT for one scope.
struct GnuplotProgram {
    explicit GnuplotProgram(const std::string& command) { setenv("T2IMU_GNUPLOT", command.c_str(), 1); }
    ~GnuplotProgram() { unsetenv("T2IMU_GNUPLOT"); }
};
}  // namespace

TEST(Gnuplot, LabelsAreQuotedAndEscaped) {
    EXPECT_EQ(gnuplot_label("walking"), "\"walking\"");
    // _ ^ { } @ get a doubled backslash (one for the string, one for enhanced text); " and \ one.
    EXPECT_EQ(gnuplot_label("acc_x"), "\"acc\\\\_x\"");
    EXPECT_EQ(gnuplot_label("m/s^2 {a}@"), "\"m/s\\\\^2 \\\\{a\\\\}\\\\@\"");
    EXPECT_EQ(gnuplot_label("say \"hi\""), "\"say \\\"hi\\\"\"");
    EXPECT_EQ(gnuplot_label("a\\b"), "\"a\\\\b\"");
}

TEST(Gnuplot, RendersAPngOfTheRequestedSizeFromInlineData) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("gnuplot_render");
    const GnuplotProgram capture("tee '" + dir + "/script.gp' | gnuplot");
    render_png(dir + "/points.png", {{"pts", {{"1", "2"}, {"3", "4"}, {"5", "\"a b\""}}}},
               "plot $pts using 1:2 with points title " + gnuplot_label("x_y"), 320, 200);
    EXPECT_EQ(png_size(dir + "/points.png"), (std::pair<uint32_t, uint32_t>{320, 200}));
    const std::string script = read_file_text(dir + "/script.gp");
    EXPECT_NE(script.find("set terminal pngcairo size 320,200"), std::string::npos) << script;
    EXPECT_NE(script.find("$pts << EOD\n1 2\n3 4\n5 \"a b\"\nEOD\n"), std::string::npos) << script;
    // Only the PNG (and the captured script) in the folder: the temporary name was renamed.
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);
}

TEST(Gnuplot, FailuresAreRefusedNamingThePngAndLeaveNothing) {
    if (test::gnuplot_missing()) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("gnuplot_fail");
    try {
        render_png(dir + "/bad.png", {}, "plot $nothing using 1:2");  // an undefined data block
        ADD_FAILURE() << "a failing script accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(dir + "/bad.png"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("gnuplot"), std::string::npos) << e.what();
    }
    {
        const GnuplotProgram broken("false");
        EXPECT_THROW(render_png(dir + "/false.png", {}, "plot x"), Error);
    }
    EXPECT_TRUE(fs::is_empty(dir));
}
