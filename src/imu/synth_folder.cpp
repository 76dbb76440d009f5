#include "imu/synth_folder.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "imu/realism.hpp"

namespace t2imu {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* tilt_key() { return realism_lever("tilt").keys[0].key; }

int optional_int(const json& doc, const char* key, const std::string& path) {
    return doc.contains(key) ? static_cast<int>(json_integer(doc, key, path)) : -1;
}

std::vector<std::string> strings(const json& doc, const char* key, const std::string& path, const std::string& where) {
    std::vector<std::string> out;
    for (const json& s : json_array(doc, key, path, where)) {
        if (!s.is_string()) throw Error(path, where + "." + key, "strings", s.dump());
        out.push_back(s.get<std::string>());
    }
    return out;
}

std::map<std::string, double> numbers(const json& doc, const char* key, const std::string& path) {
    std::map<std::string, double> out;
    if (doc.contains(key) && doc[key].is_null()) return out;  // a report of no jobs
    for (const auto& [name, v] : json_object(doc, key, path).items()) {
        if (!v.is_number()) throw Error(path, std::string(key) + "." + name, "a number", v.dump());
        out[name] = v.get<double>();
    }
    return out;
}

std::map<std::string, int> counts(const json& doc, const char* key, const std::string& path,
                                  const std::string& where = "") {
    std::map<std::string, int> out;
    const json& object = json_object(doc, key, path, where);
    for (const auto& [name, v] : object.items())
        out[name] = static_cast<int>(json_count(object, name, path, (where.empty() ? "" : where + ".") + key));
    return out;
}

MarkerRecording parse_recording(const json& r, const std::string& path, const std::string& where) {
    MarkerRecording out;
    out.path = json_string(r, "path", path, where);
    out.body = json_string(r, "body", path, where);
    out.position = json_string(r, "position", path, where);
    out.n_samples = json_count(r, "n_samples", path, where);
    if (r.contains("bytes")) out.bytes = static_cast<int64_t>(json_count(r, "bytes", path, where));
    if (r.contains("tempo")) out.tempo = json_number(r, "tempo", path, where);
    if (r.contains(tilt_key())) out.mount_tilt_deg = json_number(r, tilt_key(), path, where);
    return out;
}

}  // namespace

json job_marker_json(const JobMarker& m) {
    json attempts = json::array(), recordings = json::array();
    for (const MarkerAttempt& a : m.attempts) {
        attempts.push_back({{"seed", a.seed}, {"failures", a.failures}});
        if (a.activity_agreement) attempts.back()["activity_agreement"] = *a.activity_agreement;
    }
    for (const MarkerRecording& r : m.recordings) {
        recordings.push_back({{"path", r.path},
                              {"body", r.body},
                              {"position", r.position},
                              {"n_samples", r.n_samples},
                              {"tempo", r.tempo},
                              {tilt_key(), r.mount_tilt_deg}});
        if (r.bytes >= 0) recordings.back()["bytes"] = r.bytes;
    }
    json j = {{"job", m.job},         {"prompt", m.prompt},   {"activity", m.activity}, {"seed", m.seed},
              {"attempts", attempts}, {"quality", m.quality}, {"kept", m.kept},         {"recordings", recordings}};
    for (const auto& [key, v] :
         {std::pair<const char*, int>{"index", m.index}, {"sample", m.sample}, {"frames", m.frames}})
        if (v >= 0) j[key] = v;  // absent from markers older than the field
    if (m.sensor_motion_fps) j["sensor_motion_fps"] = *m.sensor_motion_fps;
    if (!m.source_draw.is_null()) j["source_draw"] = m.source_draw;
    if (m.coverage)
        j["coverage"] = {{"covered", m.coverage->covered},
                         {"summary", m.coverage->summary},
                         {"nearest", m.coverage->nearest},
                         {"similarity", m.coverage->similarity},
                         {"uncovered", m.coverage->uncovered}};
    if (m.activity_check)
        j["activity_check"] = {{"shown", m.activity_check->shown},
                               {"agreement", m.activity_check->agreement},
                               {"passed", m.activity_check->passed}};
    if (m.motions) {
        j["motions"] = json::array();
        for (const MarkerFile& f : *m.motions) j["motions"].push_back({{"path", f.path}, {"bytes", f.bytes}});
    }
    return j;
}

JobMarker parse_job_marker(const json& doc, const std::string& path) {
    JobMarker m;
    m.job = json_string(doc, "job", path);
    m.prompt = json_string(doc, "prompt", path);
    m.activity = json_string(doc, "activity", path);
    m.index = optional_int(doc, "index", path);
    m.sample = optional_int(doc, "sample", path);
    m.frames = optional_int(doc, "frames", path);
    m.seed = json_count(doc, "seed", path);
    m.kept = json_bool(doc, "kept", path);
    const json& attempts = json_array(doc, "attempts", path);
    for (size_t i = 0; i < attempts.size(); ++i) {
        const std::string where = "attempts." + std::to_string(i);
        MarkerAttempt a;
        a.seed = attempts[i].contains("seed") ? json_count(attempts[i], "seed", path, where) : 0;
        a.failures = strings(attempts[i], "failures", path, where);
        if (attempts[i].contains("activity_agreement"))
            a.activity_agreement = json_number(attempts[i], "activity_agreement", path, where);
        m.attempts.push_back(std::move(a));
    }
    m.quality = numbers(doc, "quality", path);
    const json& recordings = json_array(doc, "recordings", path);
    for (size_t i = 0; i < recordings.size(); ++i)
        m.recordings.push_back(parse_recording(recordings[i], path, "recordings." + std::to_string(i)));
    if (doc.contains("motions")) {
        m.motions.emplace();
        const json& motions = json_array(doc, "motions", path);
        for (size_t i = 0; i < motions.size(); ++i) {
            const std::string where = "motions." + std::to_string(i);
            m.motions->push_back({json_string(motions[i], "path", path, where),
                                  static_cast<int64_t>(json_count(motions[i], "bytes", path, where))});
        }
    }
    if (doc.contains("sensor_motion_fps")) m.sensor_motion_fps = json_number(doc, "sensor_motion_fps", path);
    if (doc.contains("activity_check")) {
        const json& c = json_object(doc, "activity_check", path);
        m.activity_check =
            ActivityCheck{json_string(c, "shown", path, "activity_check"),
                          c.contains("agreement") ? json_number(c, "agreement", path, "activity_check") : 0,
                          json_bool(c, "passed", path, "activity_check")};
    }
    if (doc.contains("source_draw")) m.source_draw = json_object(doc, "source_draw", path);
    if (doc.contains("coverage")) {
        const json& c = json_object(doc, "coverage", path);
        MarkerCoverage& v = m.coverage.emplace();
        v.covered = json_bool(c, "covered", path, "coverage");
        v.summary = json_string(c, "summary", path, "coverage");
        v.nearest = strings(c, "nearest", path, "coverage");
        for (const json& x : json_array(c, "similarity", path, "coverage")) {
            if (!x.is_number()) throw Error(path, "coverage.similarity", "numbers", x.dump());
            v.similarity.push_back(x.get<double>());
        }
        v.uncovered = strings(c, "uncovered", path, "coverage");
    }
    return m;
}

std::string job_name(int index) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "j%05d", index);
    return buf;
}

std::string job_joints_file(const std::string& job) { return "motions/" + job + "_joints.npy"; }
std::string job_bvh_file(const std::string& job) { return "motions/" + job + ".bvh"; }
std::string job_recordings_dir(const std::string& job) { return "recordings/" + job; }

std::string job_marker_path(const std::string& dir, const std::string& job) { return dir + "/jobs/" + job + ".json"; }

void write_job_marker(const std::string& dir, const JobMarker& m) {
    write_file_atomic(job_marker_path(dir, m.job), job_marker_json(m).dump(1) + "\n");
}

JobMarker read_job_marker(const std::string& path) { return parse_job_marker(read_json_file(path), path); }

std::vector<JobMarker> read_job_markers(const std::string& dir) {
    std::vector<fs::path> files;
    if (fs::is_directory(dir + "/jobs"))
        for (const auto& e : fs::directory_iterator(dir + "/jobs"))
            if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<JobMarker> markers;
    for (const fs::path& p : files) markers.push_back(read_job_marker(p.string()));
    return markers;
}

json synth_report_json(const SynthReport& r) {
    json per_activity = json::object();
    for (const auto& [activity, c] : r.per_activity) {
        json a = {{"kept", c.kept},
                  {"kept_below_activity_agreement", c.kept_below_activity_agreement},
                  {"dropped", c.dropped}};
        if (!c.shown.empty()) a["shown"] = c.shown;
        if (c.shows_activity_by_classifier) a["shows_activity_by_classifier"] = *c.shows_activity_by_classifier;
        if (c.shows_activity_by_tags) a["shows_activity_by_tags"] = *c.shows_activity_by_tags;
        per_activity[activity] = a;
    }
    const SynthRunTiming& t = r.this_run;
    const json timing = {{"jobs_run", t.jobs_run},
                         {"load_s", t.load_s},
                         {"motion_generation_s", t.motion_generation_s},
                         {"quality_scoring_s", t.quality_scoring_s},
                         {"bodies_imu_write_s", t.bodies_imu_write_s},
                         {"manifest_s", t.manifest_s},
                         {"total_s", t.total_s},
                         {"device", t.device},
                         {"threads", t.threads}};
    json j = {{"jobs", r.jobs},
              {"jobs_done", r.jobs_done},
              {"motions_kept", r.motions_kept},
              {"motions_dropped", r.motions_dropped},
              {"motions_kept_below_activity_agreement", r.motions_kept_below_activity_agreement},
              {"jobs_regenerated", r.jobs_regenerated},
              {"recordings", r.recordings},
              {"per_activity", per_activity},
              {"failed_attempts_by_score", r.failed_attempts_by_score},
              {"quality_median", r.quality_median},
              {"this_run", timing}};
    if (!r.realism.is_null()) j["realism"] = r.realism;
    return j;
}

SynthReport parse_synth_report(const json& doc, const std::string& path) {
    SynthReport r;
    const auto count = [&](const char* key) { return static_cast<int>(json_count(doc, key, path)); };
    r.jobs = count("jobs"), r.jobs_done = count("jobs_done"), r.motions_kept = count("motions_kept"),
    r.motions_dropped = count("motions_dropped");
    r.motions_kept_below_activity_agreement =
        doc.contains("motions_kept_below_activity_agreement") ? count("motions_kept_below_activity_agreement") : 0;
    r.jobs_regenerated = count("jobs_regenerated"), r.recordings = count("recordings");
    for (const auto& [activity, a] : json_object(doc, "per_activity", path).items()) {
        const std::string where = "per_activity." + activity;
        ActivityCounts& c = r.per_activity[activity];
        c.kept = static_cast<int>(json_count(a, "kept", path, where));
        c.dropped = static_cast<int>(json_count(a, "dropped", path, where));
        if (a.contains("kept_below_activity_agreement"))
            c.kept_below_activity_agreement =
                static_cast<int>(json_count(a, "kept_below_activity_agreement", path, where));
        if (a.contains("shown")) c.shown = counts(a, "shown", path, where);
        if (a.contains("shows_activity_by_classifier"))
            c.shows_activity_by_classifier =
                static_cast<int>(json_count(a, "shows_activity_by_classifier", path, where));
        if (a.contains("shows_activity_by_tags"))
            c.shows_activity_by_tags = static_cast<int>(json_count(a, "shows_activity_by_tags", path, where));
    }
    r.failed_attempts_by_score = counts(doc, "failed_attempts_by_score", path);
    r.quality_median = numbers(doc, "quality_median", path);
    const json& t = json_object(doc, "this_run", path);
    SynthRunTiming& timing = r.this_run;
    timing.jobs_run = static_cast<int>(json_count(t, "jobs_run", path, "this_run"));
    timing.threads = t.contains("threads") ? static_cast<int>(json_count(t, "threads", path, "this_run")) : 1;
    for (const auto& [key, field] : {std::pair<const char*, double*>{"load_s", &timing.load_s},
                                     {"motion_generation_s", &timing.motion_generation_s},
                                     {"quality_scoring_s", &timing.quality_scoring_s},
                                     {"bodies_imu_write_s", &timing.bodies_imu_write_s},
                                     {"manifest_s", &timing.manifest_s},
                                     {"total_s", &timing.total_s}})
        *field = t.contains(key) ? json_number(t, key, path, "this_run") : 0;
    timing.device = t.contains("device") ? json_string(t, "device", path, "this_run") : "";
    if (doc.contains("realism")) r.realism = json_object(doc, "realism", path);
    return r;
}

void write_synth_report(const std::string& dir, const SynthReport& r) {
    write_file_atomic(dir + "/synth_report.json", synth_report_json(r).dump(1) + "\n");
}

SynthReport read_synth_report(const std::string& dir) {
    const std::string path = dir + "/synth_report.json";
    return parse_synth_report(read_json_file(path), path);
}

}  // namespace t2imu
