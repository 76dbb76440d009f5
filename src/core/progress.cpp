#include "core/progress.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>

namespace t2imu {

namespace {
std::atomic<ProgressOutput> g_output{ProgressOutput::terminal_only};

std::string seconds_text(double s) {
    char buf[32];
    if (s < 90)
        std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 5400)
        std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    else
        std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
}
}  // namespace

void set_progress_output(ProgressOutput output) { g_output = output; }
ProgressOutput progress_output() { return g_output; }

Progress::Progress(std::string label, size_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      terminal_(::isatty(2) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {
    const ProgressOutput o = g_output;
    shown_ = o == ProgressOutput::always || (o == ProgressOutput::terminal_only && terminal_);
}

Progress::~Progress() { finish(); }

std::string Progress::line(const std::string& label, size_t done, size_t total, const std::string& unit,
                           double seconds) {
    char buf[160];
    const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
    std::snprintf(buf, sizeof buf, "%s: %zu/%zu%s%s, %.3g/s, %s", label.c_str(), done, total, unit.empty() ? "" : " ",
                  unit.c_str(), rate, seconds_text(seconds).c_str());
    std::string s = buf;
    if (done < total && rate > 0) s += ", ETA " + seconds_text(static_cast<double>(total - done) / rate);
    return s;
}

void Progress::advance(size_t n) {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += n;
    if (!shown_ || finished_) return;
    const auto now = std::chrono::steady_clock::now();
    if (terminal_) {
        if (now - last_draw_ < std::chrono::milliseconds(200) && done_ < total_) return;
    } else {
        if (total_ == 0 || done_ * 10 < next_tenth_ * total_) return;
        while (next_tenth_ * total_ <= done_ * 10) ++next_tenth_;
    }
    last_draw_ = now;
    draw(false);
}

void Progress::finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    finished_ = true;
    if (shown_ && (terminal_ || done_ != drawn_)) draw(true);
}

void Progress::draw(bool final) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::string text = line(label_, done_, total_, unit_, s);
    drawn_ = done_;
    if (terminal_)
        std::fprintf(stderr, "\r%s\033[K%s", text.c_str(), final ? "\n" : "");
    else
        std::fprintf(stderr, "%s\n", text.c_str());
    std::fflush(stderr);
}

}  // namespace t2imu
