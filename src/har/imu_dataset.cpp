#include "har/imu_dataset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace t2imu {

namespace {

const std::vector<std::string> kColumns = {"path", "dataset", "subject", "activity", "position", "rate_hz", "n_samples", "units"};
const std::vector<std::string> kSampleColumns = {"t", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};

void load_samples(const std::string& dir, ImuRecording& r, size_t expected) {
    const CsvTable t = read_csv(dir + "/" + r.path);
    if (t.header != kSampleColumns) throw Error(t.source, "header", "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z");
    if (t.rows.size() != expected)
        throw Error(t.source, "rows", std::to_string(expected) + " samples as the manifest says", std::to_string(t.rows.size()));
    r.t.resize(t.rows.size());
    r.samples.resize(t.rows.size());
    for (size_t i = 0; i < t.rows.size(); ++i) {
        r.t[i] = t.number(i, 0);
        for (size_t c = 0; c < 6; ++c) {
            r.samples[i][c] = t.number(i, c + 1);
            // A NaN would spread through resampling and normalisation into every window and the trained network.
            if (!std::isfinite(r.samples[i][c]))
                throw Error(t.source, "row " + std::to_string(i + 2) + " column '" + kSampleColumns[c + 1] + "'", "a finite number", "'" + t.rows[i][c + 1] + "'");
        }
        if (!std::isfinite(r.t[i]) || (i > 0 && !(r.t[i] > r.t[i - 1]))) throw Error(t.source, "row " + std::to_string(i + 2), "finite, increasing time");
    }
}

// Up to 4 decimals with trailing zeros dropped ("0", "0.05", "-9.8066").
std::string decimal4(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

}  // namespace

std::vector<ImuRecording> read_imu_dataset(const std::string& dir, bool load) {
    const CsvTable m = read_csv(dir + "/manifest.csv");
    for (const std::string& c : kColumns) m.column(c);
    std::vector<ImuRecording> out;
    for (size_t r = 0; r < m.rows.size(); ++r) {
        ImuRecording rec;
        rec.path = m.rows[r][m.column("path")];
        rec.dataset = m.rows[r][m.column("dataset")];
        rec.subject = m.rows[r][m.column("subject")];
        rec.activity = m.rows[r][m.column("activity")];
        rec.position = m.rows[r][m.column("position")];
        rec.rate_hz = m.number(r, m.column("rate_hz"));
        if (!(rec.rate_hz > 0 && std::isfinite(rec.rate_hz)))
            throw Error(m.source, "row " + std::to_string(r + 2) + " column 'rate_hz'", "a positive rate", "'" + m.rows[r][m.column("rate_hz")] + "'");
        for (size_t c = 0; c < m.header.size(); ++c)
            if (std::find(kColumns.begin(), kColumns.end(), m.header[c]) == kColumns.end()) rec.extra[m.header[c]] = m.rows[r][c];
        if (load) load_samples(dir, rec, static_cast<size_t>(m.number(r, m.column("n_samples"))));
        out.push_back(std::move(rec));
    }
    return out;
}

void write_imu_dataset(const std::string& dir, const std::vector<ImuRecording>& recordings) {
    CsvTable manifest;
    manifest.header = kColumns;
    std::set<std::string> extra;
    for (const ImuRecording& r : recordings)
        for (const auto& [k, v] : r.extra) extra.insert(k);
    manifest.header.insert(manifest.header.end(), extra.begin(), extra.end());
    for (const ImuRecording& r : recordings) {
        if (r.t.size() != r.samples.size()) throw Error(r.path, "samples", "one time per sample");
        std::string text = "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
        for (size_t i = 0; i < r.t.size(); ++i) {
            text += decimal4(r.t[i]);
            for (double v : r.samples[i]) text += "," + decimal4(v);
            text += "\n";
        }
        write_file_atomic(dir + "/" + r.path, text);
        char rate[32];
        std::snprintf(rate, sizeof rate, "%g", r.rate_hz);
        std::vector<std::string> row = {r.path, r.dataset, r.subject, r.activity, r.position, rate,
                                        std::to_string(r.samples.size()), kImuUnits};
        for (const std::string& k : extra) row.push_back(r.extra.count(k) ? r.extra.at(k) : "");
        manifest.rows.push_back(row);
    }
    write_csv(dir + "/manifest.csv", manifest);
}

}  // namespace t2imu
