#include "har/datasets/sisfall.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/signal/resample_poly.hpp"
#include "har/datasets/release_files.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

constexpr double kAccScale = 32.0 / 8192.0 * 9.80665;
constexpr double kGyroScale = 4000.0 / 65536.0 * M_PI / 180.0;

std::string activity_for(const std::string& code) {
    static const std::map<std::string, std::string> kept = {
        {"D01", "walking"},           {"D02", "walking"},           {"D03", "jogging"},
        {"D04", "jogging"},           {"D05", "stairs_up_down"},    {"D06", "stairs_up_down"},
        {"D07", "sit_down_stand_up"}, {"D09", "sit_down_stand_up"}, {"D14", "lying"},
        {"D19", "jump_reach"}};
    const auto it = kept.find(code);
    return it == kept.end() ? "" : it->second;
}

}  // namespace

std::vector<ImuRecording> read_sisfall_file(const std::string& path) {
    static const std::regex name(R"(([DF]\d\d)_(S[AE]\d\d)_(R\d\d)\.txt)");
    std::smatch m;
    const std::string file = fs::path(path).filename().string();
    if (!std::regex_match(file, m, name))
        throw Error(path, "file name", "<code>_<subject>_<trial>.txt, e.g. D05_SA01_R01.txt");
    const std::string activity = activity_for(m[1]);
    if (activity.empty()) return {};
    std::istringstream in(read_file_text(path));
    std::string line;
    int n = 0;
    std::vector<std::vector<double>> channels(6);
    while (std::getline(in, line)) {
        ++n;
        std::replace(line.begin(), line.end(), ';', ' ');
        std::replace(line.begin(), line.end(), ',', ' ');
        // Every line but a blank one is 9 finite numbers: a line of garbage or nan refuses the file (skipped and
        // named by the import) rather than vanishing from it.
        std::istringstream cells(line);
        std::vector<double> v;
        for (std::string cell; cells >> cell;) {
            const std::optional<double> x = parse_finite(cell);
            if (!x)
                throw Error(path, "line " + std::to_string(n), "9 raw values (ADXL345, ITG3200, MMA8451Q)",
                            "'" + cell.substr(0, 24) + "'");
            v.push_back(*x);
        }
        if (v.empty()) continue;
        if (v.size() != 9)
            throw Error(path, "line " + std::to_string(n), "9 raw values (ADXL345, ITG3200, MMA8451Q)",
                        std::to_string(v.size()));
        for (size_t c = 0; c < 6; ++c) channels[c].push_back(v[c] * (c < 3 ? kAccScale : kGyroScale));
    }
    if (channels[0].size() < 8) throw Error(path, "samples", "at least 8 samples at 200 Hz");
    for (auto& c : channels) c = resample_poly(c, 1, 4);
    ImuRecording r;
    r.dataset = "sisfall";
    r.subject = m[2];
    r.activity = activity;
    r.position = "waist";
    r.rate_hz = 50;
    r.path = "sisfall/" + r.subject + "/" + activity + "_" + m[1].str() + m[3].str() + "_seg0_waist.csv";
    r.extra["source_file"] = "SisFall_dataset/" + r.subject + "/" + file;
    r.extra["gyro_flag"] = "ok";
    for (size_t i = 0; i < channels[0].size(); ++i) {
        r.t.push_back(static_cast<double>(i) / 50.0);
        r.samples.push_back(
            {channels[0][i], channels[1][i], channels[2][i], channels[3][i], channels[4][i], channels[5][i]});
    }
    return {r};
}

std::vector<ImuRecording> import_sisfall(const std::string& dir, std::vector<std::string>* skipped) {
    return import_release_files(dir, std::regex(R"([DF]\d\d_S[AE]\d\d_R\d\d\.txt)"),
                                "SisFall release files (e.g. SA01/D01_SA01_R01.txt)", read_sisfall_file, skipped);
}

}  // namespace t2imu
