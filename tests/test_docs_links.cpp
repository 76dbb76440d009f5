// Every local link of the project's Markdown (README.md, docs/, bench/, models/ and the results folders' notes)
// leads to a file of the checkout, and every "#anchor" it gives matches a heading of that file (GitHub's anchors).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <vector>

#include "markdown_headings.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> project_markdown(const fs::path& root) {
    std::vector<fs::path> files = {root / "README.md"};
    for (const char* folder : {"docs", "bench", "models", "experiments"}) {
        if (!fs::exists(root / folder)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / folder))
            if (e.is_regular_file() && e.path().extension() == ".md") files.push_back(e.path());
    }
    return files;
}

// "file:line: what is wrong" for each link of `markdown` (a file below `root`) that does not resolve.
std::vector<std::string> broken_links(const fs::path& root, const fs::path& markdown) {
    std::vector<std::string> broken;
    const std::string text = t2imu::test::read_text(markdown);
    const std::regex link(R"(\]\(<?([^)#\s>]*)(#[^)\s>]*)?>?\))");
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
        const std::string target = (*it)[1], anchor = (*it)[2];
        if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
        const std::string where = fs::relative(markdown, root).string() + ":" +
                                  std::to_string(1 + std::count(text.begin(), text.begin() + it->position(), '\n'));
        const fs::path file = target.empty() ? markdown : markdown.parent_path() / target;
        if (!fs::exists(file)) {
            broken.push_back(where + ": links " + target + ", which does not exist");
        } else if (!anchor.empty() && file.extension() == ".md" &&
                   t2imu::test::markdown_headings(file).anchors.count(anchor.substr(1)) == 0) {
            broken.push_back(where + ": links " + target + anchor + ", a heading " + file.filename().string() +
                             " lacks");
        }
    }
    return broken;
}

}  // namespace

TEST(DocsLinks, AnchorsFollowGitHubsRule) {
    using t2imu::test::heading_anchor;
    EXPECT_EQ(heading_anchor("The trunk's sway (2026-12-03)"), "the-trunks-sway-2026-12-03");
    EXPECT_EQ(heading_anchor("Quick start (Debian 12, as root or with sudo)"),
              "quick-start-debian-12-as-root-or-with-sudo");
    EXPECT_EQ(heading_anchor("HAR: 75.2 ± 0.7 %"), "har-752--07-");
    EXPECT_EQ(heading_anchor("Häusler's L_acc"), "häuslers-l_acc");
}

TEST(DocsLinks, EveryLocalLinkAndAnchorResolves) {
    const fs::path root(T2IMU_SOURCE_DIR);
    const std::vector<fs::path> files = project_markdown(root);
    EXPECT_GE(files.size(), 12u);  // README, the docs pages, the model cards, bench's and the results' notes
    for (const fs::path& f : files)
        for (const std::string& b : broken_links(root, f)) ADD_FAILURE() << b;
}
