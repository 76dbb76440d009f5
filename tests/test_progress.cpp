// core/progress.cpp: the drawn line (done/total, rate, elapsed, ETA), silence when progress is off, and in a
// pipe with --verbose one line per tenth of the work and no more.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/progress.hpp"

using namespace t2imu;

namespace {
int lines_in(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

struct OutputGuard {  // restores the process-wide setting after a test
    ProgressOutput saved = progress_output();
    ~OutputGuard() { set_progress_output(saved); }
};
}  // namespace

TEST(Progress, LineShowsCountsRateElapsedAndEta) {
    EXPECT_EQ(Progress::line("synth", 3, 10, "jobs", 2.0),
              "synth: 3/10 jobs, 1.5/s, 2 s, ETA 5 s");  // 7 left at 1.5/s: 4.7 s
    EXPECT_EQ(Progress::line("HAR", 10, 10, "trainings", 300.0),
              "HAR: 10/10 trainings, 0.0333/s, 5.0 min");               // done: no ETA
    EXPECT_EQ(Progress::line("x", 0, 4, "", 0.0), "x: 0/4, 0/s, 0 s");  // no rate yet: no ETA
    EXPECT_EQ(Progress::line("train", 1, 7201, "steps", 1.0), "train: 1/7201 steps, 1/s, 1 s, ETA 2.0 h");
}

TEST(Progress, SilentWhenOff) {
    OutputGuard guard;
    set_progress_output(ProgressOutput::never);
    testing::internal::CaptureStderr();
    {
        Progress p("quiet", 5, "items");
        for (int i = 0; i < 5; ++i) p.advance();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Progress, VerboseInAPipeWritesOneLinePerTenth) {
    OutputGuard guard;
    set_progress_output(ProgressOutput::always);
    testing::internal::CaptureStderr();  // stderr is then a file, not a terminal
    {
        Progress p("loud", 40, "items");
        for (int i = 0; i < 40; ++i) p.advance();
        EXPECT_EQ(p.done(), 40u);
    }
    const std::string out = testing::internal::GetCapturedStderr();
    EXPECT_EQ(lines_in(out), 10) << out;
    EXPECT_NE(out.find("loud: 40/40 items"), std::string::npos) << out;
    EXPECT_NE(out.find("loud: 4/40 items"), std::string::npos) << out;

    testing::internal::CaptureStderr();
    {
        Progress p("cut", 40, "items");
        for (int i = 0; i < 7; ++i) p.advance();
    }  // ended early: the last state is written once when it finishes
    const std::string cut = testing::internal::GetCapturedStderr();
    EXPECT_EQ(lines_in(cut), 2) << cut;  // the 4/40 line, then 7/40 at the end
    EXPECT_NE(cut.find("cut: 7/40 items"), std::string::npos) << cut;
}
