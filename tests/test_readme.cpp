// README is a user's document (issue 44): at most 200 lines, every docs/ page linked from it, and every local
// link it gives leads to a file of the checkout (anchors are not checked).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The targets of the Markdown links "[text](target)" that are not web addresses, without their "#anchor".
std::set<std::string> local_links(const std::string& markdown) {
    std::set<std::string> out;
    const std::regex link(R"(\]\(([^)#\s]+)(#[^)\s]*)?\))");
    for (std::sregex_iterator it(markdown.begin(), markdown.end(), link), end; it != end; ++it) {
        const std::string target = (*it)[1];
        if (target.find("://") == std::string::npos && target.rfind("mailto:", 0) != 0) out.insert(target);
    }
    return out;
}

}  // namespace

TEST(Readme, IsAtMost200Lines) {
    const std::string text = read_text(fs::path(T2IMU_SOURCE_DIR) / "README.md");
    ASSERT_FALSE(text.empty());
    EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 200);
}

TEST(Readme, LinksEveryDocsPageAndEveryLocalLinkExists) {
    const fs::path root(T2IMU_SOURCE_DIR);
    const std::set<std::string> links = local_links(read_text(root / "README.md"));
    int pages = 0;
    for (const auto& e : fs::directory_iterator(root / "docs")) {
        if (e.path().extension() != ".md") continue;
        ++pages;
        EXPECT_EQ(links.count("docs/" + e.path().filename().string()), 1u)
            << e.path().filename() << " is not linked from README.md";
    }
    EXPECT_GE(pages, 8);  // 8 pages on 2026-12-04
    for (const std::string& l : links)
        EXPECT_TRUE(fs::exists(root / l)) << "README.md links " << l << ", which does not exist";
}
