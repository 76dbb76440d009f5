#include "har/datasets/umafall.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "har/datasets/release_files.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

constexpr double kRateHz = 20.0;
constexpr double kGyroLimitDeg = 256.0;

std::string activity_name(const std::string& movement) {
    static const std::map<std::string, std::string> names = {{"Walking", "walking"},
                                                             {"Jogging", "jogging"},
                                                             {"GoUpstairs", "stairs_up"},
                                                             {"GoDownstairs", "stairs_down"},
                                                             {"Hopping", "jumping"},
                                                             {"LyingDown_OnABed", "lie_down_get_up_bed"},
                                                             {"Sitting_GettingUpOnAChair", "sit_down_stand_up"},
                                                             {"Bending", "bending"},
                                                             {"Aplausing", "applauding"},
                                                             {"HandsUp", "hands_up"},
                                                             {"MakingACall", "making_a_call"},
                                                             {"OpeningDoor", "opening_door"}};
    const auto it = names.find(movement);
    return it != names.end() ? it->second : movement;
}

std::string trim(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return s.substr(i);
}

double number(const std::string& s, const std::string& path, int line) {
    return finite_number(s, path, "line " + std::to_string(line));
}

// A SensorTag reads at most ±16 g and ±2000 °/s: a sample past 10^4 in either unit is damage, not motion.
double sample_value(const std::string& s, const std::string& path, int line) {
    const double v = number(s, path, line);
    if (std::fabs(v) > 1e4) throw Error(path, "line " + std::to_string(line), "a sample within ±10^4 (g, °/s)", s);
    return v;
}

}  // namespace

std::vector<ImuRecording> read_umafall_file(const std::string& path) {
    static const std::regex name(
        R"(UMAFall_Subject_(\d+)_(ADL|Fall)_(.+)_(\d+)_(\d{4}-\d{2}-\d{2}_\d{2}-\d{2}-\d{2})\.csv)");
    std::smatch m;
    const std::string file = fs::path(path).filename().string();
    if (!std::regex_match(file, m, name))
        throw Error(path, "file name", "UMAFall_Subject_<NN>_<ADL|Fall>_<Movement>_<trial>_<date>.csv");
    if (m[2] == "Fall") return {};
    const std::string subject = "S" + m[1].str(), activity = activity_name(m[3]);

    std::istringstream in(read_file_text(path));
    std::string line;
    int n = 0;
    std::map<int, std::string> positions;  // SensorTag id -> position
    // samples[id][type][sample no] = (x, y, z)
    std::map<int, std::map<int, std::map<long, std::array<double, 3>>>> samples;
    static const std::regex tag(R"(%\s*[0-9A-Fa-f:]+;\s*(\d+);\s*(\w+);\s*SensorTag.*)");
    while (std::getline(in, line)) {
        ++n;
        line = trim(line);
        if (line.empty()) continue;
        if (line[0] == '%') {
            std::smatch t;
            if (std::regex_match(line, t, tag)) {
                std::string pos = t[2];
                std::transform(pos.begin(), pos.end(), pos.begin(), [](unsigned char c) { return std::tolower(c); });
                const int id = release_index(t[1], path, "line " + std::to_string(n) + " sensor id");
                if (positions.count(id))
                    throw Error(path, "line " + std::to_string(n) + " sensor id",
                                "an id listed once (two tags cannot share it)", t[1]);
                positions[id] = pos;
            }
            continue;
        }
        std::vector<std::string> f;
        std::stringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ';')) f.push_back(trim(cell));
        if (f.size() < 7)
            throw Error(path, "line " + std::to_string(n), "TimeStamp;Sample No;X;Y;Z;Sensor Type;Sensor ID");
        const int id = release_index(f[6], path, "line " + std::to_string(n) + " sensor id");
        const int type = release_index(f[5], path, "line " + std::to_string(n) + " sensor type");
        if (!positions.count(id) || type > 1) continue;  // the phone, or the magnetometer
        // The sample counter keys the samples: a whole number (a cast of 1e21 to long would be undefined).
        const double sample_no = number(f[1], path, n);
        if (!(sample_no >= 0 && sample_no <= 1e12 && sample_no == std::floor(sample_no)))
            throw Error(path, "line " + std::to_string(n) + " sample no", "a whole number from 0 to 10^12",
                        "'" + f[1].substr(0, 24) + "'");
        samples[id][type][static_cast<long>(sample_no)] = {sample_value(f[2], path, n), sample_value(f[3], path, n),
                                                           sample_value(f[4], path, n)};
    }
    std::vector<ImuRecording> out;
    for (const auto& [id, position] : positions) {
        ImuRecording r;
        r.dataset = "umafall";
        r.subject = subject;
        r.activity = activity;
        r.position = position;
        r.rate_hz = kRateHz;
        r.path =
            "umafall/" + subject + "/" + activity + "_" + m[4].str() + "_" + m[5].str() + "_seg0_" + position + ".csv";
        r.extra["source_file"] = "UMAFall_Dataset/" + file;
        size_t clipped = 0;
        const auto& acc = samples[id][0];
        const auto& gyr = samples[id][1];
        for (const auto& [sample_no, a] : acc) {
            const auto g = gyr.find(sample_no);
            if (g == gyr.end()) continue;
            const double k = M_PI / 180.0, s = 9.80665;
            r.t.push_back(static_cast<double>(r.t.size()) / kRateHz);
            r.samples.push_back({a[0] * s, a[1] * s, a[2] * s, g->second[0] * k, g->second[1] * k, g->second[2] * k});
            clipped += std::max({std::fabs(g->second[0]), std::fabs(g->second[1]), std::fabs(g->second[2])}) >=
                       kGyroLimitDeg - 1e-9;
        }
        if (r.samples.empty()) continue;  // a tag that streamed nothing
        r.extra["gyro_flag"] = clipped > 0.005 * static_cast<double>(r.samples.size()) ? "clipped" : "ok";
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<ImuRecording> import_umafall(const std::string& dir, std::vector<std::string>* skipped) {
    return import_release_files(dir, std::regex(R"(UMAFall_.*\.csv)"), "UMAFall_*.csv release files", read_umafall_file,
                                skipped);
}

}  // namespace t2imu
