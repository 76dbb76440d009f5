// Comments and help texts under src/ say why and link docs/ for the evidence: no measured percentage and no
// date in any comment or string literal (figures live in docs/results.md and docs/realism.md, where they are
// dated once), and every pointer they give into README.md or docs/ names a file and heading that exist.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <vector>

#include "markdown_headings.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

// A comment (consecutive // lines joined by spaces) or a string literal of a source file, with its first line.
struct Prose {
    int line;
    std::string text;
};

// Splits C++ source into its comments and string literals (raw strings included); code is skipped.
std::vector<Prose> comments_and_strings(const std::string& s) {
    std::vector<Prose> out;
    int line = 1;
    int last_line_comment_end = -1;  // the line a // comment ended on, to join the next line's
    size_t i = 0;
    const auto advance = [&](size_t to) {
        for (; i < to && i < s.size(); ++i)
            if (s[i] == '\n') ++line;
    };
    while (i < s.size()) {
        if (s.compare(i, 2, "//") == 0) {
            const size_t end = std::min(s.find('\n', i), s.size());
            std::string body = s.substr(i + 2, end - i - 2);
            if (!out.empty() && last_line_comment_end == line - 1)
                out.back().text += " " + body;
            else
                out.push_back({line, body});
            advance(end);
            last_line_comment_end = line;
        } else if (s.compare(i, 2, "/*") == 0) {
            const size_t end = std::min(s.find("*/", i + 2), s.size());
            out.push_back({line, s.substr(i + 2, end - i - 2)});
            advance(end + 2);
        } else if (s[i] == 'R' && i + 1 < s.size() && s[i + 1] == '"' &&
                   (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
            const size_t open = s.find('(', i);
            const std::string close = ")" + s.substr(i + 2, open - i - 2) + "\"";
            const size_t end = std::min(s.find(close, open), s.size());
            out.push_back({line, s.substr(open + 1, end - open - 1)});
            advance(end + close.size());
        } else if (s[i] == '"' || s[i] == '\'') {
            const char quote = s[i];
            size_t j = i + 1;
            while (j < s.size() && s[j] != quote && s[j] != '\n') j += s[j] == '\\' ? 2 : 1;
            if (quote == '"') out.push_back({line, s.substr(i + 1, j - i - 1)});
            advance(j + 1);
        } else {
            advance(i + 1);
        }
    }
    return out;
}

struct SourceFile {
    std::string name;  // below src/
    std::vector<Prose> prose;
};

std::vector<SourceFile> source_prose() {
    const fs::path src = fs::path(T2IMU_SOURCE_DIR) / "src";
    std::vector<SourceFile> files;
    for (const auto& e : fs::recursive_directory_iterator(src)) {
        const std::string ext = e.path().extension().string();
        if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp" && ext != ".h")) continue;
        files.push_back({fs::relative(e.path(), src).string(), comments_and_strings(t2imu::test::read_text(e.path()))});
    }
    return files;
}

// A percentage written as a figure ("72.2 %", "~4%"); not a format ("%5.1f%%") nor CSS ("width:100%").
const std::regex kPercentage(R"((^|[^\w.:%#])[0-9]+(\.[0-9]+)? ?%)");
// A date: 2026-12-04, 2026-12, "4 December 2026", "Dec 2026".
const std::regex kDate(
    R"(\b(19|20)[0-9]{2}-[01][0-9]\b|\b(Jan|Feb|Mar|Apr|May|Jun|Jul|Aug|Sep|Oct|Nov|Dec)[a-z]*\.? (19|20)[0-9]{2}\b)");

// A pointer into a README or docs/: "docs/page.md", "docs/page.md#anchor", `README, "Heading"`, `README's section
// "Heading"`, `docs/page.md, "Heading"` (a help text escapes the quotes). Headings may carry their date.
const std::regex kPointer(
    R"(((?:[a-z]+/)*README(\.md)?|docs/[A-Za-z0-9_-]+\.md)(#[A-Za-z0-9_-]+)?('s)?(,? +(section +)?\\?"([^"\\]+)\\?")?)");

std::vector<std::string> lab_notes(const std::vector<Prose>& prose) {
    std::vector<std::string> found;
    for (const Prose& p : prose) {
        const std::string text = std::regex_replace(p.text, kPointer, "$1");  // a heading's date is the docs'
        std::smatch m;
        if (std::regex_search(text, m, kPercentage) || std::regex_search(text, m, kDate))
            found.push_back(std::to_string(p.line) + ": \"" + m.str() + "\" in: " + text.substr(0, 160));
    }
    return found;
}

}  // namespace

TEST(SourceComments, TheScannerFindsFiguresAndDatesInCommentsAndStringsOnly) {
    const std::vector<Prose> prose = comments_and_strings(
        "int a = 7 % 2;  // HAR rose to 72.2 % (2026-12-06)\n"
        "// a second line\n"
        "const char* f = \"%5.1f%%\", *css = \"img{max-width:100%}\";\n"
        "/* made 4 December 2026 */ auto r = R\"x(raw \"50%\" text)x\";\n"
        "// why, in a line (docs/realism.md#the-trunks-sway-2026-12-03; docs/realism.md, \"Lying turns "
        "(2026-12-03)\")\n");
    ASSERT_EQ(prose.size(), 6u);
    EXPECT_EQ(prose[0].text, " HAR rose to 72.2 % (2026-12-06)  a second line");
    EXPECT_EQ(prose[3].line, 4);
    const std::vector<std::string> found = lab_notes(prose);
    ASSERT_EQ(found.size(),
              3u);  // the comment, the block comment, the raw string; not the format, CSS, `7 % 2`, pointers
    EXPECT_NE(found[0].find("\" 72.2 %\""), std::string::npos) << found[0];
    EXPECT_NE(found[1].find("December 2026"), std::string::npos) << found[1];
    EXPECT_NE(found[2].find("\"50%\""), std::string::npos) << found[2];
}

TEST(SourceComments, NoMeasuredPercentageOrDateInSrc) {
    const std::vector<SourceFile> files = source_prose();
    EXPECT_GE(files.size(), 200u);
    for (const SourceFile& f : files)
        for (const std::string& note : lab_notes(f.prose))
            ADD_FAILURE() << "src/" << f.name << ":" << note
                          << "\n  (figures and dates go to docs/results.md or docs/realism.md)";
}

// Each pointer (kPointer) names a file that exists, and its anchor or quoted heading is one of that file's headings.
TEST(SourceComments, EveryPointerIntoReadmeOrDocsResolves) {
    const fs::path root(T2IMU_SOURCE_DIR);
    int pointers = 0;
    for (const SourceFile& f : source_prose()) {
        for (const Prose& p : f.prose) {
            for (std::sregex_iterator it(p.text.begin(), p.text.end(), kPointer), end; it != end; ++it) {
                const std::string page = (*it)[1].str() == "README" ? "README.md" : (*it)[1].str();
                const std::string anchor = (*it)[3],
                                  heading = std::regex_replace((*it)[7].str(), std::regex(" +"), " ");
                const std::string where = "src/" + f.name + ":" + std::to_string(p.line) + ": " + it->str();
                ++pointers;
                if (!fs::exists(root / page)) {
                    ADD_FAILURE() << where << ": " << page << " does not exist";
                    continue;
                }
                const t2imu::test::Headings h = t2imu::test::markdown_headings(root / page);
                if (!anchor.empty() && h.anchors.count(anchor.substr(1)) == 0)
                    ADD_FAILURE() << where << ": " << page << " has no heading with the anchor " << anchor;
                if (!heading.empty() && h.texts.count(heading) == 0)
                    ADD_FAILURE() << where << ": " << page << " has no heading \"" << heading << "\"";
            }
        }
    }
    EXPECT_GE(pointers, 10);
}
