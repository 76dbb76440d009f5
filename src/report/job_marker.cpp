#include "report/job_marker.hpp"

#include "core/error.hpp"
#include "core/json_file.hpp"

namespace t2imu {

void check_job_marker(const nlohmann::json& m, const std::string& path) {
    for (const char* key : {"job", "prompt", "activity"}) json_string(m, key, path);
    json_count(m, "seed", path);
    json_bool(m, "kept", path);
    for (size_t i = 0; i < json_array(m, "attempts", path).size(); ++i) {
        const std::string where = "attempts." + std::to_string(i);
        for (const nlohmann::json& f : json_array(m["attempts"][i], "failures", path, where))
            if (!f.is_string()) throw Error(path, where + ".failures", "names of quality scores", f.dump());
    }
    for (const auto& [name, v] : json_object(m, "quality", path).items())
        if (!v.is_number()) throw Error(path, "quality." + name, "a number", v.dump());
    const nlohmann::json& recordings = json_array(m, "recordings", path);
    for (size_t i = 0; i < recordings.size(); ++i) {
        const std::string where = "recordings." + std::to_string(i);
        for (const char* key : {"path", "body", "position"}) json_string(recordings[i], key, path, where);
        json_count(recordings[i], "n_samples", path, where);
        if (recordings[i].contains("bytes")) json_count(recordings[i], "bytes", path, where);
    }
    if (m.contains("motions"))
        for (size_t i = 0; i < json_array(m, "motions", path).size(); ++i) {
            json_string(m["motions"][i], "path", path, "motions." + std::to_string(i));
            json_count(m["motions"][i], "bytes", path, "motions." + std::to_string(i));
        }
    if (m.contains("activity_check")) {
        json_string(json_object(m, "activity_check", path), "shown", path, "activity_check");
        json_bool(m["activity_check"], "passed", path, "activity_check");
    }
    if (m.contains("source_draw")) json_object(m, "source_draw", path);
}

}  // namespace t2imu
