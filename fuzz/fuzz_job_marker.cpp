// libFuzzer target: a synthesis job marker (jobs/<job>.json) of arbitrary bytes through the JSON reader and
// check_job_marker, then every field read the way the synthesis reads a checked marker. A t2imu::Error is a
// correct answer; a crash, an uncaught JSON exception or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/json_file.hpp"
#include "report/job_marker.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const nlohmann::json m = t2imu::parse_json_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
        t2imu::check_job_marker(m, "fuzz.json");
        (void)m["kept"].get<bool>();
        for (const nlohmann::json& r : m["recordings"]) (void)r["n_samples"].get<size_t>(), (void)r["path"].get<std::string>();
        for (const auto& [name, v] : m["quality"].items()) (void)v.get<double>();
        for (const nlohmann::json& a : m["attempts"])
            for (const nlohmann::json& f : a["failures"]) (void)f.get<std::string>();
        if (m.contains("activity_check")) (void)m["activity_check"]["shown"].get<std::string>();
    } catch (const t2imu::Error&) {
    }
    return 0;
}
