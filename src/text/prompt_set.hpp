// Prompt sets (prompts/*.tsv): one prompt per line, or `activity<TAB>prompt` where activity is the class name
// the synthetic recordings are labelled with (the IMU dataset layout's canonical names, or a real data set's
// own). Lines starting with # and empty lines are skipped; a trailing CR is dropped. Text must be valid UTF-8
// without control characters: prompts end up in JSON, CSV and the text encoder, which all need that.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace t2imu {

struct Prompt {
    std::string activity;  // "" when the line has no tab
    std::string text;
};

// Whether every line must name its activity (synth labels its recordings with it).
enum class PromptActivity { optional, required };

// Refuses an unreadable, empty or oversized file (kMaxPromptFileBytes), and a bad line naming the file and its line
// number: a blank prompt or activity, control and bidi control characters. A byte-order mark at the start is dropped.
constexpr size_t kMaxPromptFileBytes = size_t{16} << 20;
std::vector<Prompt> read_prompt_set(const std::string& path, PromptActivity activity = PromptActivity::optional);
// The same on a prompt set's text, errors naming `source`.
std::vector<Prompt> parse_prompt_set(const std::string& text, const std::string& source,
                                     PromptActivity activity = PromptActivity::optional);

// Throws Error naming `source` and `field` unless `text` is valid UTF-8 without control or bidi control characters.
void check_prompt_text(const std::string& text, const std::string& source, const std::string& field);

}  // namespace t2imu
