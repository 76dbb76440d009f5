#include <gtest/gtest.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(Csv, QuotedFieldsCommasNewlinesAndCrlf) {
    const CsvTable t =
        parse_csv("file,caption,n\r\na.bvh,\"jump, balance\",3\r\nb.bvh,\"say \"\"hi\"\"\nand go\",4", "x.csv");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][1], "jump, balance");
    EXPECT_EQ(t.rows[1][1], "say \"hi\"\nand go");
    EXPECT_EQ(t.number(1, t.column("n")), 4.0);
    EXPECT_EQ(parse_csv(format_csv(t), "again.csv").rows, t.rows);
}

TEST(Csv, EmptyFieldsAndTrailingNewline) {
    const CsvTable t = parse_csv("a,b,c\n1,,3\n,,\n", "e.csv");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0], (std::vector<std::string>{"1", "", "3"}));
    EXPECT_EQ(t.rows[1], (std::vector<std::string>{"", "", ""}));
}

TEST(Csv, ErrorsNameTheLineAndColumn) {
    try {
        parse_csv("a,b\n1,2\n3\n", "short.csv");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("short.csv: line 3"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parse_csv("a,b\n\"open,2\n", "q.csv"), Error);
    const CsvTable t = parse_csv("a,b\nx,2\n", "n.csv");
    EXPECT_THROW(t.number(0, 0), Error);
    EXPECT_THROW(t.column("missing"), Error);
}

TEST(Csv, ReadsTheSharedMocapManifest) {
    std::string path;
    SHARED_OR_SKIP(path, "mocap/captions.csv");
    const CsvTable t = read_csv(path);
    EXPECT_EQ(t.header.size(), 7u);
    EXPECT_EQ(t.rows.size(), 1187u);  // the shared README's caption count (v5: 1,121 + 66 ReActIdle)
    EXPECT_EQ(t.rows[0][t.column("caption")], "walk");
}
