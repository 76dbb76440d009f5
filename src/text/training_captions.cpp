#include "text/training_captions.hpp"

#include <set>
#include <utility>

#include "core/atomic_file.hpp"
#include "data/clip_activities.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

std::vector<Prompt> training_captions(const Hml3dDataset& data, const std::string& dataset_dir) {
    const auto tagged = read_clip_activities(dataset_dir);
    std::set<std::pair<std::string, std::string>> seen;
    std::vector<Prompt> out;
    for (const MotionClip& clip : data.clips())
        for (const CaptionLine& line : clip.captions) {
            const auto tags = tagged.find(clip_file_id(clip.id));
            std::vector<std::string> activities =
                tags != tagged.end() ? tags->second : std::vector<std::string>{activity_named_in(line.caption)};
            for (std::string& a : activities) {
                if (a.empty()) a = "other";
                if (seen.insert({a, line.caption}).second) out.push_back({a, line.caption});
            }
        }
    return out;
}

void write_training_captions(const std::string& path, const std::vector<Prompt>& captions) {
    std::string text = "# the captions a model was trained on, each under its clip's activity (activity<TAB>caption)\n";
    for (const Prompt& c : captions) text += c.activity + "\t" + c.text + "\n";
    write_file_atomic(path, text);
}

}  // namespace t2imu
