#include "data/hml3d_dataset.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/npy.hpp"

namespace t2imu {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> read_ids(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path, "split", "a list of clip ids, one per line");
    std::vector<std::string> ids;
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) ids.push_back(line);
    }
    return ids;
}

}  // namespace

Hml3dDataset::Hml3dDataset(const std::string& dir, const std::string& split) {
    stats_ = read_feature_stats(dir + "/Mean.npy", dir + "/Std.npy");
    for (const std::string& id : read_ids(dir + "/" + split + ".txt")) {
        const std::string motion_path = dir + "/new_joint_vecs/" + id + ".npy";
        const std::string text_path = dir + "/texts/" + id + ".txt";
        if (!fs::exists(motion_path) || !fs::exists(text_path)) {
            ++skipped_;
            continue;
        }
        const FeatureMatrix motion = feature_matrix_from_array(read_npy(motion_path), motion_path);
        MotionClip whole{id, motion, {}};
        bool used = false;
        for (const CaptionLine& line : read_caption_file(text_path)) {
            if (line.whole_clip()) {
                whole.captions.push_back(line);
                continue;
            }
            // Text2MotionDatasetV2 cuts motion[int(start*20) : int(end*20)].
            const Eigen::Index a = static_cast<Eigen::Index>(line.start_s * 20.0);
            const Eigen::Index b = std::min<Eigen::Index>(static_cast<Eigen::Index>(line.end_s * 20.0), motion.rows());
            if (b <= a || !usable_length(b - a)) continue;
            CaptionLine l = line;
            l.start_s = l.end_s = 0;
            clips_.push_back(
                {id + "#" + std::to_string(a) + "-" + std::to_string(b), motion.middleRows(a, b - a), {l}});
            used = true;
        }
        if (!whole.captions.empty() && usable_length(motion.rows())) {
            clips_.push_back(std::move(whole));
            used = true;
        }
        if (!used) ++skipped_;
    }
    if (clips_.empty())
        throw Error(dir + "/" + split + ".txt", "clips", "at least one motion of 40-199 frames with a caption");
    seed(0);
}

void Hml3dDataset::seed(uint64_t seed) {
    rng_.seed(seed);
    order_.resize(clips_.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = i;
    std::shuffle(order_.begin(), order_.end(), rng_);
    cursor_ = 0;
}

std::string Hml3dDataset::state() const {
    std::ostringstream out;
    out << rng_ << ' ' << cursor_ << ' ' << order_.size();
    for (size_t i : order_) out << ' ' << i;
    return out.str();
}

void Hml3dDataset::restore_state(const std::string& state) {
    std::istringstream in(state);
    size_t n = 0;
    in >> rng_ >> cursor_ >> n;
    if (!in || n != clips_.size())
        throw Error("dataset state", "clips", std::to_string(clips_.size()), std::to_string(n));
    order_.resize(n);
    for (size_t& i : order_) in >> i;
    if (!in || cursor_ > n) throw Error("dataset state", "order", "a saved draw state");
}

Batch Hml3dDataset::next_batch(int batch_size) {
    Batch b;
    b.size = batch_size;
    b.features.assign(static_cast<size_t>(batch_size) * kMaxMotionFrames * 263, 0.0f);
    b.mask.assign(static_cast<size_t>(batch_size) * kMaxMotionFrames, 0);
    for (int i = 0; i < batch_size; ++i) {
        if (cursor_ == order_.size()) {
            std::shuffle(order_.begin(), order_.end(), rng_);
            cursor_ = 0;
        }
        const MotionClip& clip = clips_[order_[cursor_++]];
        const std::string caption =
            clip.captions[std::uniform_int_distribution<size_t>(0, clip.captions.size() - 1)(rng_)].caption;
        int length = static_cast<int>(clip.features.rows());
        const bool shorter = std::uniform_int_distribution<int>(0, 2)(rng_) == 2;  // 'double' in MDM: 1 in 3
        length = (length / kUnitLength - (shorter ? 1 : 0)) * kUnitLength;
        length = std::min(length, kMaxMotionFrames);
        const int start = std::uniform_int_distribution<int>(0, static_cast<int>(clip.features.rows()) - length)(rng_);
        const FeatureMatrix window = normalize_features(clip.features.middleRows(start, length), stats_);
        for (int t = 0; t < length; ++t) {
            for (int c = 0; c < 263; ++c)
                b.features[(static_cast<size_t>(i) * kMaxMotionFrames + static_cast<size_t>(t)) * 263 +
                           static_cast<size_t>(c)] = static_cast<float>(window(t, c));
            b.mask[static_cast<size_t>(i) * kMaxMotionFrames + static_cast<size_t>(t)] = 1;
        }
        b.lengths.push_back(length);
        b.captions.push_back(caption);
        b.ids.push_back(clip.id);
    }
    return b;
}

}  // namespace t2imu
