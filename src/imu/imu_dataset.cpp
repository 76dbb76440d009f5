#include "imu/imu_dataset.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/output_path.hpp"
#include "text/utf8.hpp"

namespace t2imu {

namespace {

const std::vector<std::string> kColumns = {"path",     "dataset", "subject",   "activity",
                                           "position", "rate_hz", "n_samples", "units"};
const std::vector<std::string> kSampleColumns = {"t", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};

std::string sample_header() {
    std::string line;
    for (const std::string& c : kSampleColumns) line += (line.empty() ? "" : ",") + c;
    return line;
}

void load_samples(const std::string& dir, ImuRecording& r, size_t expected) {
    const CsvTable t = read_csv(dir + "/" + r.path);
    if (t.header != kSampleColumns) throw Error(t.source, "header", sample_header());
    if (t.rows.size() != expected)
        throw Error(t.source, "rows", std::to_string(expected) + " samples as the manifest says",
                    std::to_string(t.rows.size()));
    r.t.resize(t.rows.size());
    r.samples.resize(t.rows.size());
    for (size_t i = 0; i < t.rows.size(); ++i) {
        r.t[i] = t.number(i, 0);
        for (size_t c = 0; c < 6; ++c) {
            r.samples[i][c] = t.number(i, c + 1);
            // A NaN would spread through resampling and normalisation into every window and the trained network.
            if (!std::isfinite(r.samples[i][c]))
                throw Error(t.source, "row " + std::to_string(i + 2) + " column '" + kSampleColumns[c + 1] + "'",
                            "a finite number", "'" + t.rows[i][c + 1] + "'");
        }
        if (!std::isfinite(r.t[i]) || (i > 0 && !(r.t[i] > r.t[i - 1])))
            throw Error(t.source, "row " + std::to_string(i + 2), "finite, increasing time");
    }
}

// A sample past these is a numerical failure upstream (an unstable filter, a corrupt import), not motion: the
// widest MEMS ranges are about 4e3 m/s^2 (400 g) and 35 rad/s; time in s, a recording shorter than ~30 years.
constexpr double kMaxSample = 1e6;  // m/s^2 and rad/s
constexpr double kMaxTime = 1e9;    // s

// Refuses a row the reader would refuse or that would be a wall of digits, naming the file, row and column.
void check_sample_row(const std::string& file, size_t row, double t, const double* six) {
    const auto refuse = [&](size_t column, double v, const char* expected) {
        throw Error(file, "row " + std::to_string(row + 2) + " column '" + kSampleColumns[column] + "'", expected,
                    general_text(v, 6));
    };
    if (!(std::isfinite(t) && std::fabs(t) <= kMaxTime)) refuse(0, t, "a finite time within 1e9 s");
    for (size_t c = 0; c < 6; ++c)
        if (!(std::isfinite(six[c]) && std::fabs(six[c]) <= kMaxSample))
            refuse(c + 1, six[c], "a finite sample within ±1e6 (m/s², rad/s)");
}

void append_sample_row(std::string& out, double t, const double* six, int decimals) {
    append_fixed(out, t, 4);  // rates to 10 kHz
    for (int c = 0; c < 6; ++c) {
        out += ',';
        append_fixed(out, six[c], decimals);
    }
    out += '\n';
}

}  // namespace

const std::vector<std::string>& imu_sample_columns() { return kSampleColumns; }

std::vector<ImuRecording> read_imu_dataset(const std::string& dir, bool load) {
    const CsvTable m = read_csv(dir + "/manifest.csv");
    for (const std::string& c : kColumns) m.column(c);
    std::vector<ImuRecording> out;
    for (size_t r = 0; r < m.rows.size(); ++r) {
        for (size_t c = 0; c < m.header.size() && c < m.rows[r].size(); ++c)  // names go into JSON and reports
            if (first_invalid_utf8(m.rows[r][c]) != std::string::npos)
                throw Error(m.source, "row " + std::to_string(r + 2) + " column '" + m.header[c] + "'", "UTF-8 text",
                            "bytes that are not UTF-8");
        ImuRecording rec;
        rec.path = m.rows[r][m.column("path")];
        confined_path(dir, rec.path, m.source + " row " + std::to_string(r + 2) + " column 'path'");
        rec.dataset = m.rows[r][m.column("dataset")];
        rec.subject = m.rows[r][m.column("subject")];
        rec.activity = m.rows[r][m.column("activity")];
        rec.position = m.rows[r][m.column("position")];
        rec.rate_hz = m.number(r, m.column("rate_hz"));
        if (!(rec.rate_hz > 0 && std::isfinite(rec.rate_hz)))
            throw Error(m.source, "row " + std::to_string(r + 2) + " column 'rate_hz'", "a positive rate",
                        "'" + m.rows[r][m.column("rate_hz")] + "'");
        for (size_t c = 0; c < m.header.size(); ++c)
            if (std::find(kColumns.begin(), kColumns.end(), m.header[c]) == kColumns.end())
                rec.extra[m.header[c]] = m.rows[r][c];
        const double n = m.number(r, m.column("n_samples"));
        if (!(n >= 0 && n <= 1e12 && n == std::floor(n)))
            throw Error(m.source, "row " + std::to_string(r + 2) + " column 'n_samples'",
                        "a whole number of samples from 0", "'" + m.rows[r][m.column("n_samples")] + "'");
        rec.n_samples = static_cast<size_t>(n);
        if (load) load_samples(dir, rec, rec.n_samples);
        out.push_back(std::move(rec));
    }
    return out;
}

void write_imu_dataset(const std::string& dir, const std::vector<ImuRecording>& recordings, int decimals) {
    std::vector<ImuRecording> written;
    for (const ImuRecording& r : recordings) {
        if (r.t.size() != r.samples.size()) throw Error(r.path, "samples", "one time per sample");
        std::string text = sample_header() + "\n";
        text.reserve(text.size() + r.t.size() * 64);
        const std::string file = confined_path(dir, r.path, dir + "/manifest.csv path");
        for (size_t i = 0; i < r.t.size(); ++i) {
            check_sample_row(file, i, r.t[i], r.samples[i].data());
            append_sample_row(text, r.t[i], r.samples[i].data(), decimals);
        }
        write_file_atomic(file, text);
        ImuRecording row = r;
        row.n_samples = r.samples.size();
        row.t.clear();
        row.samples.clear();
        written.push_back(std::move(row));
    }
    write_imu_manifest(dir, written);
}

void write_imu_recording(const std::string& path, const ImuSignals& s, int decimals) {
    std::string text = sample_header() + "\n";
    text.reserve(text.size() + s.t.size() * 64);
    for (size_t k = 0; k < s.t.size(); ++k) {
        const double six[6] = {s.acc[k].x(), s.acc[k].y(), s.acc[k].z(), s.gyr[k].x(), s.gyr[k].y(), s.gyr[k].z()};
        check_sample_row(path, k, s.t[k], six);
        append_sample_row(text, s.t[k], six, decimals);
    }
    write_file_atomic(path, text);
}

void write_imu_manifest(const std::string& dir, const std::vector<ImuRecording>& recordings,
                        const std::vector<std::string>& extra_order) {
    CsvTable manifest;
    manifest.header = kColumns;
    std::set<std::string> extra;
    for (const ImuRecording& r : recordings)
        for (const auto& [k, v] : r.extra) extra.insert(k);
    std::vector<std::string> extra_columns;
    for (const std::string& k : extra_order)
        if (extra.erase(k)) extra_columns.push_back(k);
    extra_columns.insert(extra_columns.end(), extra.begin(), extra.end());
    manifest.header.insert(manifest.header.end(), extra_columns.begin(), extra_columns.end());
    for (const ImuRecording& r : recordings) {
        std::vector<std::string> row = {r.path,
                                        r.dataset,
                                        r.subject,
                                        r.activity,
                                        r.position,
                                        general_text(r.rate_hz, 6),
                                        std::to_string(r.n_samples),
                                        kImuUnits};
        for (const std::string& k : extra_columns) row.push_back(r.extra.count(k) ? r.extra.at(k) : "");
        manifest.rows.push_back(row);
    }
    write_csv(dir + "/manifest.csv", manifest);
}

void check_position_held(const std::vector<ImuRecording>& recordings, const std::string& position,
                         const std::string& option, bool sided) {
    std::set<std::string> held;
    for (const ImuRecording& r : recordings) held.insert(r.position);
    const auto matches = [&](const std::string& h) {
        return h == position || (sided && (h == "left_" + position || h == "right_" + position));
    };
    if (std::any_of(held.begin(), held.end(), matches)) return;
    std::string list;
    for (const std::string& h : held) list += (list.empty() ? "" : ", ") + h;
    throw Error(option, position, "a position the data set holds (" + list + ")");
}

}  // namespace t2imu
