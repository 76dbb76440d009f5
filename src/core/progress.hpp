// A long job's progress on stderr: "label: done/total unit, rate/s, elapsed, ETA". On a terminal the line is
// redrawn in place (at most five times a second) and ended when the job finishes; in a pipe nothing is written
// unless progress was made verbose (the CLI's --verbose), and then one line per tenth of the work, so logs stay
// short. advance() may be called from any thread.
#pragma once
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace t2imu {

enum class ProgressOutput { terminal_only, always, never };
void set_progress_output(ProgressOutput output);  // the process-wide choice; terminal_only by default
ProgressOutput progress_output();

class Progress {
public:
    Progress(std::string label, size_t total, std::string unit = "");
    ~Progress();  // finishes the line if finish() was not called
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void advance(size_t n = 1);
    void finish();
    size_t done() const { return done_; }

    // "label: 3/10 jobs, 1.5/s, 2 s, ETA 5 s" for the given state; what is drawn.
    static std::string line(const std::string& label, size_t done, size_t total, const std::string& unit,
                            double seconds);

private:
    void draw(bool final);
    std::string label_, unit_;
    size_t total_, done_ = 0, next_tenth_ = 1, drawn_ = 0;  // drawn_: done_ at the last line written
    bool shown_, terminal_, finished_ = false;
    std::chrono::steady_clock::time_point start_, last_draw_;
    std::mutex mutex_;
};

}  // namespace t2imu
