// How well a model's training captions cover a prompt: whether the activity it asks for has training captions
// at all, the captions nearest it (caption_index.hpp) and their similarity, and the attributes its words ask
// for (data/measured_captions.hpp: slowly, left, backwards, "then", ...) that no training caption of that
// activity names. A prompt outside what the model learned still draws a motion, but from the text encoder's
// guess: `synth` and `sample` warn about it, record it in the job marker and the report, and refuse it with
// --require-coverage.
#pragma once
#include <string>
#include <vector>

#include "text/caption_index.hpp"

namespace t2imu {

struct PromptCoverage {
    std::string activity;              // canonical (activity_asked), "" when the prompt names none
    bool activity_known = false;       // the training captions hold that activity
    std::vector<std::string> nearest;  // the nearest training captions of that activity, nearest first
    std::vector<double> similarity;    // their SIF cosine
    std::vector<std::string> attributes_asked;
    std::vector<std::string> attributes_uncovered;  // asked, but named by no training caption of the activity
    bool covered() const { return activity_known && attributes_uncovered.empty(); }
    std::string summary()
        const;  // one line: "activity 'ironing' has no training captions", "... never name: pace_slow"
};

constexpr size_t kCoverageNeighbours = 3;

// `label`: the prompt set's activity label ("" for none).
PromptCoverage prompt_coverage(const CaptionIndex& index, const std::string& label, const std::string& prompt);

// Every prompt's coverage, before any output: one warning line on stderr per prompt not covered
// ("t2imu: warning: SOURCE: prompt N: ..."), or with `require` an Error naming the first (--require-coverage).
std::vector<PromptCoverage> check_prompts_covered(const CaptionIndex& index, const std::vector<Prompt>& prompts,
                                                  const std::string& source, bool require);

// What a model's training captions cover, as Markdown: per activity, its distinct captions and how many of them
// name each attribute (data/measured_captions.hpp's attribute words). docs/coverage.md is this for models/default.
std::string coverage_markdown(const std::vector<Prompt>& captions, const std::string& model);

}  // namespace t2imu
