#include <gtest/gtest.h>

#include "core/error.hpp"
#include "data/captions.hpp"

using namespace t2imu;

TEST(Captions, ParsesHumanML3DLines) {
    const CaptionLine c = parse_caption_line("a man kicks with something#a/DET man/NOUN kick/VERB#0.0#0.0", "t.txt");
    EXPECT_EQ(c.caption, "a man kicks with something");
    EXPECT_EQ(c.tokens, "a/DET man/NOUN kick/VERB");
    EXPECT_TRUE(c.whole_clip());
    const CaptionLine s = parse_caption_line("he waves#he/PRON wave/VERB#1.5#4.0", "t.txt");
    EXPECT_DOUBLE_EQ(s.start_s, 1.5);
    EXPECT_DOUBLE_EQ(s.end_s, 4.0);
    EXPECT_TRUE(parse_caption_line("x##nan#nan", "t.txt").whole_clip());
    EXPECT_EQ(format_caption_line(s), "he waves#he/PRON wave/VERB#1.5#4.0");
    EXPECT_THROW(parse_caption_line("no tags here", "t.txt"), Error);
    EXPECT_THROW(parse_caption_line("x##3.0#1.0", "t.txt"), Error);
}

TEST(Captions, SwapsLeftAndRightAsWholeWords) {
    EXPECT_EQ(swap_left_right("Left hand up, then the right leg; LEFT again"),
              "Right hand up, then the left leg; RIGHT again");
    EXPECT_EQ(swap_left_right("he leftover rightly"), "he leftover rightly");
}
