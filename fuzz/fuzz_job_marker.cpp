// libFuzzer target: a synthesis job marker (jobs/<job>.json) of arbitrary bytes through the JSON reader and
// parse_job_marker (report/synth_folder.hpp), then written back and read again: what parses must round-trip. A
// t2imu::Error is a correct answer; a crash, an uncaught JSON exception, a failed round trip or a sanitizer report
// is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/json_file.hpp"
#include "report/synth_folder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const nlohmann::json doc =
            t2imu::parse_json_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
        const t2imu::JobMarker m = t2imu::parse_job_marker(doc, "fuzz.json");
        const nlohmann::json back = t2imu::job_marker_json(m);
        if (t2imu::job_marker_json(t2imu::parse_job_marker(back, "back.json")) != back) std::abort();
    } catch (const t2imu::Error&) {}
    return 0;
}
