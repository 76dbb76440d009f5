#include "har/datasets/realworld.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/zip_archive.hpp"
#include "har/datasets/release_files.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

struct Stream {
    std::vector<double> t_ms;
    std::vector<std::array<double, 3>> xyz;
};

struct StreamKey {
    std::string activity;
    int part;
    std::string position;
    bool operator<(const StreamKey& o) const {
        return std::tie(activity, part, position) < std::tie(o.activity, o.part, o.position);
    }
};

using Streams = std::map<StreamKey, std::array<Stream, 2>>;  // [0] acc, [1] gyro

Stream parse_stream(const std::vector<uint8_t>& bytes, const std::string& source) {
    const CsvTable t = parse_csv(std::string(bytes.begin(), bytes.end()), source);
    const size_t time = t.column("attr_time"), x = t.column("attr_x"), y = t.column("attr_y"), z = t.column("attr_z");
    std::vector<std::pair<double, std::array<double, 3>>> rows;
    // A finite number in every cell: a nan would be written through and refused by the dataset's own reader.
    const auto finite = [&](size_t r, size_t c) {
        const double v = t.number(r, c);
        if (!std::isfinite(v))
            throw Error(source, "row " + std::to_string(r + 2) + " column '" + t.header[c] + "'", "a finite number",
                        t.rows[r][c]);
        return v;
    };
    for (size_t r = 0; r < t.rows.size(); ++r)
        rows.push_back({finite(r, time), {finite(r, x), finite(r, y), finite(r, z)}});
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    Stream s;
    for (const auto& [ms, v] : rows)
        if (s.t_ms.empty() || ms > s.t_ms.back()) {  // a repeated timestamp keeps its first sample
            s.t_ms.push_back(ms);
            s.xyz.push_back(v);
        }
    return s;
}

// Collects the CSV members of an archive, descending into nested zips.
void collect(const ZipMembers& members, const std::string& source, Streams& streams) {
    static const std::regex csv(R"((?:.*/)?(acc|Gyroscope)_([a-z]+)(?:_(\d+))?_([a-z]+)\.csv)");
    for (const auto& [name, bytes] : members) {
        if (name.size() > 4 && ends_with(name, ".zip")) {
            collect(parse_zip(bytes.data(), bytes.size(), source + ":" + name), source + ":" + name, streams);
            continue;
        }
        std::smatch m;
        if (!std::regex_match(name, m, csv)) continue;
        const StreamKey key{m[2], m[3].matched ? release_index(m[3], source + ":" + name, "part number") : 1, m[4]};
        streams[key][m[1] == "acc" ? 0 : 1] = parse_stream(bytes, source + ":" + name);
    }
}

std::array<double, 3> interpolate(const Stream& s, double t_ms) {
    const auto hi = std::lower_bound(s.t_ms.begin(), s.t_ms.end(), t_ms);
    const size_t j = static_cast<size_t>(hi - s.t_ms.begin());
    if (j == 0) return s.xyz.front();
    if (j >= s.t_ms.size()) return s.xyz.back();
    const double a = (t_ms - s.t_ms[j - 1]) / (s.t_ms[j] - s.t_ms[j - 1]);
    std::array<double, 3> v;
    for (size_t k = 0; k < 3; ++k) v[k] = (1 - a) * s.xyz[j - 1][k] + a * s.xyz[j][k];
    return v;
}

std::string canonical_activity(const std::string& a) {
    if (a == "climbingdown") return "stairs_down";
    if (a == "climbingup") return "stairs_up";
    return a;
}

}  // namespace

std::vector<ImuRecording> read_realworld_proband(const std::string& proband_dir, std::vector<std::string>* skipped) {
    const std::string subject = fs::path(proband_dir).filename().string();
    const std::string data = proband_dir + "/data";
    if (!fs::is_directory(data))
        throw Error(proband_dir, "data", "a data/ folder of <sensor>_<activity>_csv.zip archives");
    Streams streams;
    std::vector<std::string> zips;
    for (const auto& e : fs::directory_iterator(data))
        if (e.path().extension() == ".zip") zips.push_back(e.path().string());
    std::sort(zips.begin(), zips.end());
    for (const std::string& z : zips) collect(read_zip(z), z, streams);

    // Group the positions of each session part and put them on one grid.
    std::map<std::pair<std::string, int>, std::vector<StreamKey>> parts;
    for (const auto& [key, pair] : streams) {
        if (pair[0].t_ms.size() < 2 || pair[1].t_ms.size() < 2) {
            if (skipped)
                skipped->push_back(subject + " " + key.activity + " part " + std::to_string(key.part) + " " +
                                   key.position + ": accelerometer or gyroscope file missing");
            continue;
        }
        parts[{key.activity, key.part}].push_back(key);
    }
    std::vector<ImuRecording> out;
    for (const auto& [part, keys] : parts) {
        double t0 = -1e300, t1 = 1e300;
        for (const StreamKey& k : keys)
            for (const Stream& s : streams[k]) {
                t0 = std::max(t0, s.t_ms.front());
                t1 = std::min(t1, s.t_ms.back());
            }
        const double step_ms = 1000.0 / kRealWorldRateHz;
        if (t1 - t0 < step_ms) {
            if (skipped)
                skipped->push_back(subject + " " + part.first + " part " + std::to_string(part.second) +
                                   ": streams do not overlap");
            continue;
        }
        const size_t n = static_cast<size_t>(std::floor((t1 - t0) / step_ms + 1e-9)) + 1;
        for (const StreamKey& k : keys) {
            ImuRecording r;
            r.dataset = "realworld";
            r.subject = subject;
            r.activity = canonical_activity(k.activity);
            r.position = k.position;
            r.rate_hz = kRealWorldRateHz;
            r.path = "realworld/" + subject + "/" + r.activity + "_" + std::to_string(k.part) + "_seg0_" + k.position +
                     ".csv";
            r.extra["source_file"] = subject + "/data/*_" + k.activity + "_csv.zip";
            r.extra["start_ms"] = std::to_string(static_cast<long long>(std::llround(t0)));
            const auto& [acc, gyr] = streams[k];
            for (size_t i = 0; i < n; ++i) {
                const double t = t0 + static_cast<double>(i) * step_ms;
                const auto a = interpolate(acc, t), g = interpolate(gyr, t);
                r.t.push_back(static_cast<double>(i) / kRealWorldRateHz);
                r.samples.push_back({a[0], a[1], a[2], g[0], g[1], g[2]});
            }
            out.push_back(std::move(r));
        }
    }
    return out;
}

std::vector<ImuRecording> import_realworld(const std::string& dir, std::vector<std::string>* skipped) {
    std::vector<std::string> probands;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && e.path().filename().string().rfind("proband", 0) == 0)
            probands.push_back(e.path().string());
    if (probands.empty()) throw Error(dir, "folders", "proband<N>/ folders of the RealWorld release");
    std::sort(probands.begin(), probands.end());
    std::vector<ImuRecording> out;
    for (const std::string& p : probands) {
        std::vector<ImuRecording> r = read_realworld_proband(p, skipped);
        out.insert(out.end(), r.begin(), r.end());
    }
    if (out.empty())
        throw Error(dir, "recordings",
                    "at least one usable recording among " + std::to_string(probands.size()) + " proband folders",
                    skipped && !skipped->empty() ? "none; first refusal: " + skipped->front() : "none");
    return out;
}

}  // namespace t2imu
