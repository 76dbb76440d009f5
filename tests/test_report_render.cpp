// The report as a browser shows it: a synthesis folder's page rendered by headless Chromium (Debian's
// `chromium`; scripts/setup.sh installs it) to a PNG that must have the window's size and not be blank, and
// the page's pose strips and BVH links, one per kept motion, each link resolving to a file.
#include <gtest/gtest.h>
#include <zlib.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>

#include "core/atomic_file.hpp"
#include "report/html_report.hpp"
#include "report_fixture.hpp"
#include "test_util.hpp"

using namespace t2imu;
namespace fs = std::filesystem;

namespace {

uint32_t be32(const std::vector<uint8_t>& b, size_t at) {
    return (uint32_t{b[at]} << 24) | (uint32_t{b[at + 1]} << 16) | (uint32_t{b[at + 2]} << 8) | uint32_t{b[at + 3]};
}

struct Image {
    uint32_t width = 0, height = 0;
    std::vector<std::array<uint8_t, 3>> rgb;  // row-major
};

int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// An 8-bit RGB or RGBA, non-interlaced PNG (what Chromium writes): IHDR, the IDAT stream inflated, the rows
// unfiltered (PNG spec, section 9).
Image decode_png(const std::vector<uint8_t>& png) {
    Image im;
    std::vector<uint8_t> z;
    int channels = 0;
    for (size_t at = 8; at + 8 <= png.size();) {
        const uint32_t length = be32(png, at);
        const std::string type(png.begin() + static_cast<long>(at) + 4, png.begin() + static_cast<long>(at) + 8);
        if (type == "IHDR") {
            im.width = be32(png, at + 8);
            im.height = be32(png, at + 12);
            EXPECT_EQ(png[at + 16], 8) << "bit depth";
            EXPECT_EQ(png[at + 20], 0) << "interlace";
            channels = png[at + 17] == 6 ? 4 : png[at + 17] == 2 ? 3 : 0;
        } else if (type == "IDAT") {
            z.insert(z.end(), png.begin() + static_cast<long>(at) + 8,
                     png.begin() + static_cast<long>(at + 8 + length));
        }
        at += 12 + length;
    }
    if (channels == 0 || im.width == 0) return im;
    const size_t stride = im.width * static_cast<size_t>(channels);
    std::vector<uint8_t> raw((stride + 1) * im.height);
    uLongf size = raw.size();
    if (uncompress(raw.data(), &size, z.data(), z.size()) != Z_OK || size != raw.size()) return {};
    std::vector<uint8_t> previous(stride, 0), row(stride);
    for (uint32_t y = 0; y < im.height; ++y) {
        const uint8_t filter = raw[y * (stride + 1)];
        for (size_t i = 0; i < stride; ++i) {
            const int x = raw[y * (stride + 1) + 1 + i], a = i >= static_cast<size_t>(channels) ? row[i - channels] : 0,
                      b = previous[i], c = i >= static_cast<size_t>(channels) ? previous[i - channels] : 0;
            const int predicted = filter == 1   ? a
                                  : filter == 2 ? b
                                  : filter == 3 ? (a + b) / 2
                                  : filter == 4 ? paeth(a, b, c)
                                                : 0;
            row[i] = static_cast<uint8_t>(x + predicted);
        }
        for (uint32_t px = 0; px < im.width; ++px)
            im.rgb.push_back({row[px * channels], row[px * channels + 1], row[px * channels + 2]});
        previous = row;
    }
    return im;
}

bool has_command(const std::string& name) {
    return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

}  // namespace

TEST(ReportRender, SynthesisPageRendersWithAStripAndBvhLinkPerKeptMotion) {
    if (!has_command("chromium"))
        GTEST_SKIP() << "chromium not installed (scripts/setup.sh installs it for this screenshot test)";
    if (!has_command("gnuplot")) GTEST_SKIP() << "gnuplot not installed (scripts/setup.sh installs gnuplot-nox)";
    const std::string dir = test::scratch_dir("report_render"), in = dir + "/synth", report = in + "/report";
    test::write_synth_fixture(in);
    write_report(in, report);  // no real data: the figures then hold no orange (see the last check)

    const std::string html = read_file_text(report + "/index.html");
    size_t strips = 0;
    for (size_t p = html.find("<svg class=\"pose-strip\""); p != std::string::npos;
         p = html.find("<svg class=\"pose-strip\"", p + 1))
        ++strips;
    EXPECT_EQ(strips, 2u);  // the fixture's kept motions
    const std::regex link("<a class=\"bvh\" href=\"([^\"]+)\">");
    std::set<std::string> targets;
    for (auto m = std::sregex_iterator(html.begin(), html.end(), link); m != std::sregex_iterator(); ++m) {
        const fs::path target = fs::path(report) / (*m)[1].str();  // as the browser resolves it
        EXPECT_TRUE(fs::is_regular_file(target)) << target;
        targets.insert(fs::weakly_canonical(target).string());
    }
    EXPECT_EQ(targets, (std::set<std::string>{fs::weakly_canonical(in + "/motions/j00000.bvh").string(),
                                              fs::weakly_canonical(in + "/motions/j00001.bvh").string()}));

    const std::string shot = dir + "/screenshot.png";
    const std::string command =
        "timeout 60 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir=" + dir +
        "/chromium-profile --screenshot=" + shot + " --window-size=1200,2000 file://" +
        fs::absolute(report + "/index.html").string() + " > " + dir + "/chromium.log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << read_file_text(dir + "/chromium.log");
    const Image im = decode_png(read_file_bytes(shot));
    EXPECT_EQ(im.width, 1200u);
    EXPECT_EQ(im.height, 2000u);
    ASSERT_EQ(im.rgb.size(), size_t{im.width} * im.height) << "could not decode " << shot;
    // Not blank: text, tables, pose strips and figures cover several per cent of a white page; and the strips'
    // bones are drawn (left limbs #3b75af, right #e08a2c; without real data no figure uses that orange).
    size_t inked = 0, orange = 0;
    for (const auto& p : im.rgb) {
        inked += p[0] < 200 || p[1] < 200 || p[2] < 200;
        orange += std::abs(p[0] - 0xe0) < 12 && std::abs(p[1] - 0x8a) < 12 && std::abs(p[2] - 0x2c) < 12;
    }
    EXPECT_GT(inked, im.rgb.size() / 50) << inked << " dark pixels";
    EXPECT_GT(orange, 200u) << "pose strip bones";
}
