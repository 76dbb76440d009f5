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
#include <fstream>
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

namespace {

std::string binary() {
    const char* other = std::getenv("T2IMU_TEST_BINARY");
    return other && *other ? other : T2IMU_BINARY;
}

// `calls` through one t2imu process in its batch mode (src/cli/main.cpp: T2IMU_CLI_BATCH): the shell splits each
// call's words as it would for run_cli, and each call's record comes back as "EXIT\nLENGTH\n" and its output.
std::vector<CliResult> run_cli_batch(const std::vector<std::string>& calls) {
    static std::atomic<int> batches{0};
    const std::string script =
        scratch_dir("cli_batch/" + std::to_string(getpid()) + "-" + std::to_string(batches++)) + "/calls.sh";
    {
        std::ofstream out(script);
        for (const std::string& c : calls) out << "set -- " << c << "\nprintf '%s\\0' \"$#\" \"$@\"\n";
    }
    const CliResult batch = run_shell("sh '" + script + "' | T2IMU_CLI_BATCH=1 '" + binary() + "'");
    std::vector<CliResult> results(calls.size(), CliResult{-1, "batch mode failed: " + batch.output.substr(0, 2000)});
    std::istringstream in(batch.output);
    for (CliResult& r : results) {
        int code = 0;
        size_t length = 0;
        if (!(in >> code >> length) || in.get() != '\n') break;
        std::string output(length, '\0');
        if (!in.read(output.data(), static_cast<std::streamsize>(length))) break;
        r = {code, output};
    }
    return results;
}

}  // namespace

CliResult run_cli(const std::string& args) { return run_shell("'" + binary() + "' " + args); }

std::vector<CliResult> run_cli_each(const std::vector<std::string>& calls) {
    // Each call in a process of its own is kept for another build (it may predate the batch mode).
    const bool own_processes = std::getenv("T2IMU_TEST_BINARY") && *std::getenv("T2IMU_TEST_BINARY");
    const size_t parts = std::max(2u, std::thread::hardware_concurrency());
    std::vector<CliResult> results(calls.size());
    std::vector<std::thread> workers;
    std::atomic<size_t> next{0};
    for (size_t w = 0; w < parts; ++w)
        workers.emplace_back([&, w] {
            if (own_processes) {
                for (size_t i = next++; i < calls.size(); i = next++) results[i] = run_cli(calls[i]);
                return;
            }
            std::vector<std::string> mine;  // every parts-th call, so slow probes spread over the batches
            for (size_t i = w; i < calls.size(); i += parts) mine.push_back(calls[i]);
            const std::vector<CliResult> done = run_cli_batch(mine);
            for (size_t j = 0; j < done.size(); ++j) results[w + j * parts] = done[j];
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

// The names listed under "Subcommands:" in a --help text.
std::vector<std::string> subcommands_in(const std::string& help) {
    std::istringstream in(help);
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

}  // namespace

const std::vector<CliLeaf>& cli_leaves() {
    static const std::vector<CliLeaf> all = [] {
        std::vector<CliLeaf> found;
        for (std::vector<std::string> level = {""}; !level.empty();) {
            std::vector<std::string> calls, next;
            for (const std::string& path : level) calls.push_back(path + " --help");
            const std::vector<CliResult> helps = run_cli_each(calls);
            for (size_t i = 0; i < level.size(); ++i) {
                const std::vector<std::string> children = subcommands_in(helps[i].output);
                if (children.empty() && !level[i].empty()) found.push_back({level[i], helps[i].output});
                for (const std::string& c : children) next.push_back(level[i].empty() ? c : level[i] + " " + c);
            }
            level = next;
        }
        std::sort(found.begin(), found.end(), [](const CliLeaf& a, const CliLeaf& b) { return a.path < b.path; });
        return found;
    }();
    return all;
}

std::vector<std::string> cli_leaf_commands() {
    std::vector<std::string> paths;
    for (const CliLeaf& leaf : cli_leaves()) paths.push_back(leaf.path);
    return paths;
}

std::vector<CliOption> cli_options_of(const std::string& leaf) {
    const std::vector<CliLeaf>& leaves = cli_leaves();
    const auto it = std::find_if(leaves.begin(), leaves.end(), [&](const CliLeaf& l) { return l.path == leaf; });
    std::vector<CliOption> out;
    std::istringstream in(it == leaves.end() ? std::string() : it->help);
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
