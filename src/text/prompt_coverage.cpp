#include "text/prompt_coverage.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "core/error.hpp"
#include "data/measured_captions.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

std::string PromptCoverage::summary() const {
    if (activity.empty()) return "names no activity the model knows";
    if (!activity_known) return "activity '" + activity + "' has no training captions";
    if (attributes_uncovered.empty()) return "covered";
    std::string s = "the training captions of '" + activity + "' never name:";
    for (const std::string& a : attributes_uncovered) s += " " + a;
    return s;
}

PromptCoverage prompt_coverage(const CaptionIndex& index, const std::string& label, const std::string& prompt) {
    PromptCoverage c;
    c.activity = activity_asked(label, prompt);
    c.attributes_asked = attributes_asked(prompt);
    if (c.activity.empty()) return c;
    for (const CaptionNeighbour& n : index.nearest(prompt, kCoverageNeighbours, c.activity)) {
        c.nearest.push_back(index.captions()[n.index].text);
        c.similarity.push_back(n.similarity);
    }
    c.activity_known = !c.nearest.empty();
    std::vector<std::string> named;  // attributes some training caption of the activity names
    for (const Prompt& caption : index.captions())
        if (shows_activity(caption.activity, c.activity))
            for (const std::string& a : attributes_asked(caption.text))
                if (std::find(named.begin(), named.end(), a) == named.end()) named.push_back(a);
    for (const std::string& a : c.attributes_asked)
        if (std::find(named.begin(), named.end(), a) == named.end()) c.attributes_uncovered.push_back(a);
    return c;
}

std::vector<PromptCoverage> check_prompts_covered(const CaptionIndex& index, const std::vector<Prompt>& prompts,
                                                  const std::string& source, bool require) {
    std::vector<PromptCoverage> out;
    for (size_t i = 0; i < prompts.size(); ++i) {
        out.push_back(prompt_coverage(index, prompts[i].activity, prompts[i].text));
        if (out.back().covered()) continue;
        const std::string where = source + ": prompt " + std::to_string(i + 1);
        if (require)
            throw Error(where, "--require-coverage", "a prompt the model's training captions cover",
                        out.back().summary());
        std::fprintf(stderr, "t2imu: warning: %s: %s\n", where.c_str(), out.back().summary().c_str());
    }
    return out;
}

std::string coverage_markdown(const std::vector<Prompt>& captions, const std::string& model) {
    std::map<std::string, std::set<std::string>> texts;  // activity -> distinct captions
    for (const Prompt& c : captions) texts[c.activity.empty() ? "other" : c.activity].insert(c.text);
    std::string md =
        "# What `" + model + "` covers\n\nMade by `t2imu text coverage --model " + model +
        "` from the model's training captions (`captions.tsv`): per activity, its distinct captions and how many name "
        "each "
        "attribute a prompt can ask for ([attributes.md](attributes.md)). A prompt asking for an activity or an "
        "attribute "
        "with no caption here is reported uncovered by `t2imu synth` and `t2imu sample`.\n\n| activity | captions |";
    for (const AttributeWords& a : attribute_words()) md += " " + a.attribute + " |";
    md += "\n|---|---|";
    for (size_t i = 0; i < attribute_words().size(); ++i) md += "---|";
    md += "\n";
    for (const auto& [activity, set] : texts) {
        md += "| " + activity + " | " + std::to_string(set.size()) + " |";
        for (const AttributeWords& a : attribute_words()) {
            int n = 0;
            for (const std::string& t : set) {
                const std::vector<std::string> asked = attributes_asked(t);
                n += std::find(asked.begin(), asked.end(), a.attribute) != asked.end();
            }
            md += " " + std::to_string(n) + " |";
        }
        md += "\n";
    }
    return md;
}

}  // namespace t2imu
