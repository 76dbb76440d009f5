#include "report/gnuplot.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

// Writes `input` to the pipe with SIGPIPE blocked on this thread: a gnuplot that exits before reading it all (a
// bad script, a program that is not gnuplot) closes the pipe under the write, and the signal would kill the whole
// process instead of the error that names the figure. A SIGPIPE the write raised is taken off before unblocking.
void write_ignoring_broken_pipe(FILE* pipe, const std::string& input) {
    sigset_t pipe_signal, old;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_signal, &old);
    std::fwrite(input.data(), 1, input.size(), pipe);
    std::fflush(pipe);
    const timespec now{0, 0};
    while (sigtimedwait(&pipe_signal, nullptr, &now) == SIGPIPE) {}
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

}  // namespace

std::string gnuplot_label(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@') out += "\\\\";  // literal in enhanced text
        out += c;
    }
    return out + "\"";
}

void render_png(const std::string& png_path, const std::vector<GnuplotData>& data, const std::string& script, int width,
                int height) {
    const char* program = std::getenv("T2IMU_GNUPLOT");
    const std::string tmp = temporary_path_for(png_path);
    std::string input = "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
                        " enhanced font 'DejaVu Sans,11'\nset output '" + tmp + "'\n";
    for (const GnuplotData& d : data) {
        input += "$" + d.name + " << EOD\n";
        for (const auto& row : d.rows) {
            for (size_t i = 0; i < row.size(); ++i) input += (i ? " " : "") + row[i];
            input += "\n";
        }
        input += "EOD\n";
    }
    input += script + "\nunset output\n";
    const std::string command = std::string(program ? program : "gnuplot") + " 2>&1";
    FILE* pipe = popen(command.c_str(), "w");
    if (!pipe) throw Error(png_path, "gnuplot", "gnuplot on the PATH (Debian package gnuplot-nox)");
    write_ignoring_broken_pipe(pipe, input);
    const int status = pclose(pipe);
    if (status != 0 || !std::filesystem::exists(tmp) || std::filesystem::file_size(tmp) == 0) {
        std::filesystem::remove(tmp);
        throw Error(png_path, "gnuplot", "a successful run (is gnuplot-nox installed?)",
                    "exit status " + std::to_string(status));
    }
    commit_temporary(tmp, png_path);
}

}  // namespace t2imu
