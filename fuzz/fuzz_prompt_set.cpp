// libFuzzer target: a prompt set (prompts/*.tsv) read from arbitrary bytes, with the activity optional and
// required. A t2imu::Error is a correct answer; a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "text/prompt_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (t2imu::PromptActivity a : {t2imu::PromptActivity::optional, t2imu::PromptActivity::required}) {
        try {
            (void)t2imu::parse_prompt_set(text, "fuzz.tsv", a);
        } catch (const t2imu::Error&) {}
    }
    return 0;
}
