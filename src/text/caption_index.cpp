#include "text/caption_index.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "data/measured_captions.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

CaptionIndex::CaptionIndex(const WordVectors& vectors, const std::vector<Prompt>& captions, const std::string& source)
    : sif_(vectors) {
    std::set<std::pair<std::string, std::string>> seen;
    std::vector<std::string> texts;
    for (const Prompt& c : captions)
        if (seen.insert({c.activity, c.text}).second) {
            captions_.push_back(c);
            texts.push_back(c.text);
            named_.push_back(attributes_asked(c.text));
        }
    sif_.fit_common_component(texts);
    unit_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(captions_.size()), WordVectors::kDims);
    bool any = false;
    for (size_t i = 0; i < captions_.size(); ++i) {
        const Eigen::VectorXd e = sif_.embed(texts[i]);
        if (e.norm() == 0) continue;
        unit_.row(static_cast<Eigen::Index>(i)) = e.transpose() / e.norm();
        any = true;
    }
    if (!any)
        throw Error(source, "captions", "at least one caption with a word of the vocabulary",
                    std::to_string(captions_.size()) + " captions, none");
}

std::vector<CaptionNeighbour> CaptionIndex::nearest(const std::string& prompt, size_t k, const std::string& activity,
                                                    bool match_attributes) const {
    std::vector<size_t> candidates;
    if (activity.empty()) return {};
    for (size_t i = 0; i < captions_.size(); ++i)
        if (shows_activity(captions_[i].activity, activity)) candidates.push_back(i);
    if (candidates.empty()) return {};
    const Eigen::VectorXd e = sif_.embed(prompt);
    const double norm = e.norm();
    const Eigen::VectorXd cosines =
        norm > 0 ? Eigen::VectorXd(unit_ * (e / norm)) : Eigen::VectorXd::Zero(unit_.rows());
    const std::vector<std::string> asked = match_attributes ? attributes_asked(prompt) : std::vector<std::string>{};
    std::vector<size_t> shared(captions_.size(), 0);
    for (size_t i : candidates) shared[i] = attributes_shared(asked, named_[i]);
    std::sort(candidates.begin(), candidates.end(), [&](size_t a, size_t b) {
        const double ca = cosines[static_cast<Eigen::Index>(a)], cb = cosines[static_cast<Eigen::Index>(b)];
        if (shared[a] != shared[b]) return shared[a] > shared[b];
        return ca != cb ? ca > cb : a < b;
    });
    // Only the nearest caption's own activity: a direction-agnostic "stairs" takes one direction, never a blend of
    // up and down (see the header).
    const std::string& chosen = captions_[candidates.front()].activity;
    std::vector<CaptionNeighbour> out;
    for (size_t i : candidates)
        if (out.size() < k && captions_[i].activity == chosen)
            out.push_back({i, cosines[static_cast<Eigen::Index>(i)]});
    return out;
}

}  // namespace t2imu
