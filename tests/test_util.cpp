#include "test_util.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/error.hpp"

namespace t2imu::test {

namespace fs = std::filesystem;

std::string source_dir() { return T2IMU_SOURCE_DIR; }

bool gnuplot_missing() { return std::system("gnuplot --version > /dev/null 2>&1") != 0; }

std::string shared_data_dir() {
    if (const char* env = std::getenv("T2IMU_SHARED_DATA")) return fs::is_directory(env) ? env : "";
    const fs::path p = fs::path(T2IMU_SOURCE_DIR).parent_path() / "shared" / "data";
    return fs::is_directory(p) ? p.string() : "";
}

std::string shared_path(const std::string& relative) {
    const std::string root = shared_data_dir();
    if (root.empty()) return "";
    const fs::path p = fs::path(root) / relative;
    return fs::exists(p) ? p.string() : "";
}

std::string unpacked_shared_archive(const std::string& relative_archive) {
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    const std::string archive = shared_path(relative_archive);
    if (archive.empty()) return "";
    const fs::path dest = fs::path(T2IMU_TEST_TMP) / "unpacked" / relative_archive;
    fs::create_directories(dest.parent_path());
    // CTest runs tests in parallel processes: an exclusive file lock makes one of them unpack while the others wait.
    const std::string lock_path = dest.string() + ".lock";
    const int fd = open(lock_path.c_str(), O_CREAT | O_RDWR, 0644);
    if (fd < 0 || flock(fd, LOCK_EX) != 0) return "";
    const fs::path done = dest / ".complete";
    bool ok = fs::exists(done);
    if (!ok) {
        fs::remove_all(dest);
        fs::create_directories(dest);
        const std::string cmd = "tar -xJf '" + archive + "' -C '" + dest.string() + "'";
        ok = std::system(cmd.c_str()) == 0;
        if (ok) {
            std::FILE* f = std::fopen(done.c_str(), "w");
            if (f) std::fclose(f);
        }
    }
    flock(fd, LOCK_UN);
    close(fd);
    return ok ? dest.string() : "";
}

std::string scratch_dir(const std::string& name) {
    const fs::path p = fs::path(T2IMU_TEST_TMP) / "scratch" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

CliResult run_cli(const std::string& args) {
    const char* other = std::getenv("T2IMU_TEST_BINARY");
    return run_shell(std::string("'") + (other && *other ? other : T2IMU_BINARY) + "' " + args);
}

std::vector<CliResult> run_cli_each(const std::vector<std::string>& calls) {
    std::vector<CliResult> results(calls.size());
    std::atomic<size_t> next{0};
    std::vector<std::thread> workers(std::max(2u, std::thread::hardware_concurrency()));
    for (std::thread& w : workers)
        w = std::thread([&] {
            for (size_t i = next++; i < calls.size(); i = next++) results[i] = run_cli(calls[i]);
        });
    for (std::thread& w : workers) w.join();
    return results;
}

CliResult run_shell(const std::string& command) {
    const std::string cmd = command + " 2>&1";
    CliResult r{-1, ""};
    std::FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

namespace {

std::vector<std::string> subcommands_of(const std::string& path) {
    std::istringstream in(run_cli(path + " --help").output);
    std::vector<std::string> names;
    bool listing = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("Subcommands:", 0) == 0) {
            listing = true;
            continue;
        }
        if (!listing) continue;
        if (line.size() < 3 || line[0] != ' ' || line[2] == ' ') break;  // the list ends at a blank or unindented line
        std::istringstream words(line);
        std::string name;
        words >> name;
        names.push_back(name);
    }
    return names;
}

void collect_leaves(const std::string& path, std::vector<std::string>* leaves) {
    const std::vector<std::string> children = subcommands_of(path);
    if (children.empty() && !path.empty()) leaves->push_back(path);
    for (const std::string& c : children) collect_leaves(path.empty() ? c : path + " " + c, leaves);
}

}  // namespace

std::vector<std::string> cli_leaf_commands() {
    std::vector<std::string> leaves;
    collect_leaves("", &leaves);
    return leaves;
}

std::vector<CliOption> cli_options_of(const std::string& leaf) {
    std::vector<CliOption> out;
    std::istringstream in(run_cli(leaf + " --help").output);
    bool listing = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("Options:", 0) == 0 || line.rfind("Positionals:", 0) == 0) {
            listing = true;
            continue;
        }
        if (!listing || line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;
        std::istringstream words(line);
        CliOption o;
        words >> o.name >> o.type;
        if (o.name.rfind("-h,", 0) == 0 || (o.name.rfind("--", 0) != 0 && o.name[0] == '-'))
            continue;  // help, short-only flags
        std::getline(words, o.help);
        o.positional = o.name[0] != '-';
        o.required = line.find("REQUIRED") != std::string::npos;
        out.push_back(o);
    }
    return out;
}

std::string error_message(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no Error thrown";
    return "";
}

WordVectors axis_vocabulary(const std::vector<std::pair<std::string, std::vector<float>>>& words) {
    std::vector<std::string> names;
    std::vector<float> v;
    for (const auto& [w, coordinates] : words) {
        names.push_back(w);
        std::vector<float> row(WordVectors::kDims, 0.0f);
        std::copy(coordinates.begin(), coordinates.end(), row.begin());
        v.insert(v.end(), row.begin(), row.end());
    }
    return WordVectors(names, v);
}

}  // namespace t2imu::test
