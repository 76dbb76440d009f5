// Every shipped model folder has a short model card of one template: what it is, how it was trained (with the
// commit of its weights), its figures in one table, its licence; at most 80 lines (the record is docs/results.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include "markdown_headings.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

// The text of the "## title" section of a card, up to the next "## ".
std::string card_section(const std::string& card, const std::string& title) {
    const size_t start = card.find("\n## " + title + "\n");
    if (start == std::string::npos) return "";
    const size_t end = card.find("\n## ", start + 4);
    return card.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace

TEST(ModelCards, EveryModelFolderHasAShortCardOfTheTemplate) {
    int cards = 0;
    for (const auto& e : fs::directory_iterator(fs::path(T2IMU_SOURCE_DIR) / "models")) {
        // A folder still holding its training's checkpoint is a training's output (`t2imu train --out models/x`),
        // not a shipped model: the release ships weights and a card, no checkpoint.
        if (!e.is_directory() || !fs::exists(e.path() / "model.json") || fs::exists(e.path() / "checkpoint.pt"))
            continue;
        ++cards;
        const std::string name = e.path().filename().string();
        const std::string card = t2imu::test::read_text(e.path() / "README.md");
        ASSERT_FALSE(card.empty()) << "models/" << name << " has no README.md";
        EXPECT_LE(std::count(card.begin(), card.end(), '\n'), 80) << "models/" << name << "/README.md";
        EXPECT_EQ(card.rfind("# models/" + name + ": ", 0), 0u) << "models/" << name << ": the title names the folder";
        const std::set<std::string> headings = t2imu::test::markdown_headings(e.path() / "README.md").texts;
        for (const char* title : {"What it is", "How it was trained", "Figures", "Licence"})
            EXPECT_EQ(headings.count(title), 1u) << "models/" << name << "/README.md lacks \"## " << title << "\"";
        EXPECT_TRUE(std::regex_search(card_section(card, "How it was trained"), std::regex(R"(\b[0-9a-f]{7,40}\b)")))
            << "models/" << name << ": how it was trained names no commit";
        const std::string figures = card_section(card, "Figures");
        EXPECT_NE(figures.find("\n|---"), std::string::npos) << "models/" << name << ": the figures are not a table";
    }
    EXPECT_GE(cards, 2);
}
