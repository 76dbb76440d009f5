#include "har/datasets/hugadb.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "har/datasets/release_files.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

const char* kActivities[] = {"walking",     "running",  "stairs_up", "stairs_down", "sitting",       "sitting_down",
                             "standing_up", "standing", "bicycling", "elevator_up", "elevator_down", "sitting_in_car"};
const char* kPositions[] = {"right_foot", "right_shin", "right_thigh", "left_foot", "left_shin", "left_thigh"};
constexpr double kAccScale = 2.0 / 32768.0 * 9.80665;
constexpr double kGyroScale = 2000.0 / 32768.0 * M_PI / 180.0;

// "HuGaDB_v1_walking_01_00.txt" (or "..._00-Test.txt") -> subject "s01", trial "00".
void subject_and_trial(const std::string& path, std::string& subject, std::string& trial) {
    std::string stem = fs::path(path).stem().string();
    const size_t test = stem.find("-Test");
    if (test != std::string::npos) stem.resize(test);
    const size_t b = stem.rfind('_'), a = b == std::string::npos ? b : stem.rfind('_', b - 1);
    if (a == std::string::npos) throw Error(path, "file name", "HuGaDB_v1_<activity>_<subject>_<trial>.txt");
    subject = "s" + stem.substr(a + 1, b - a - 1);
    trial = stem.substr(b + 1);
}

}  // namespace

std::vector<ImuRecording> read_hugadb_file(const std::string& path) {
    std::string subject, trial;
    subject_and_trial(path, subject, trial);
    std::istringstream in(read_file_text(path));
    std::string line;
    int n = 0;
    std::vector<std::vector<double>> rows;
    std::vector<int> activity;
    while (std::getline(in, line)) {
        ++n;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) continue;
        std::istringstream cells(line);
        std::vector<double> v;
        for (std::string cell; cells >> cell && v.size() <= 39;) {
            const std::optional<double> x = parse_number(cell);
            if (!x) throw Error(path, "line " + std::to_string(n), "39 numbers (6 IMUs x 6, 2 EMG, activity)", cell);
            v.push_back(*x);
        }
        if (v.size() != 39)
            throw Error(path, "line " + std::to_string(n), "39 numbers (6 IMUs x 6, 2 EMG, activity)",
                        std::to_string(v.size()));
        // Checked as a double first: casting -1.9e10 to int is undefined behaviour (found by fuzz_hugadb).
        if (!(v[38] >= 1 && v[38] <= 12 && v[38] == std::floor(v[38])))
            throw Error(path, "line " + std::to_string(n), "an activity id from 1 to 12", std::to_string(v[38]));
        const int act = static_cast<int>(v[38]);
        rows.push_back(std::move(v));
        activity.push_back(act);
    }
    if (rows.empty()) throw Error(path, "data", "at least one sample row");
    std::vector<ImuRecording> out;
    size_t start = 0;
    for (int seg = 0; start < rows.size(); ++seg) {
        size_t end = start;
        while (end < rows.size() && activity[end] == activity[start]) ++end;
        for (int p = 0; p < 6; ++p) {
            ImuRecording r;
            r.dataset = "hugadb";
            r.subject = subject;
            r.activity = kActivities[activity[start] - 1];
            r.position = kPositions[p];
            r.rate_hz = kHuGaDBRateHz;
            r.path = "hugadb/" + subject + "/" + r.activity + "_" + trial + "_seg" + std::to_string(seg) + "_" +
                     r.position + ".csv";
            r.extra["source_file"] = fs::path(path).filename().string();
            r.extra["gyro_flag"] = "unknown";
            for (size_t i = start; i < end; ++i) {
                r.t.push_back(static_cast<double>(i - start) / kHuGaDBRateHz);
                std::array<double, 6> s;
                for (int c = 0; c < 6; ++c)
                    s[static_cast<size_t>(c)] =
                        rows[i][static_cast<size_t>(6 * p + c)] * (c < 3 ? kAccScale : kGyroScale);
                r.samples.push_back(s);
            }
            out.push_back(std::move(r));
        }
        start = end;
    }
    return out;
}

std::vector<ImuRecording> import_hugadb(const std::string& dir) {
    return import_release_files(dir, std::regex(R"(HuGaDB_v1_.*\.txt)"), "HuGaDB_v1_*.txt release files",
                                read_hugadb_file, nullptr);
}

}  // namespace t2imu
