#include "pipeline/motion_source.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <random>

#include "core/error.hpp"
#include "data/hml3d_dataset.hpp"
#include "motion/humanml3d.hpp"
#include "text/sentence_similarity.hpp"

namespace t2imu {

namespace {

class DiffusionSource : public MotionSource {
public:
    DiffusionSource(const std::string& dir, const SampleOptions& sampling, const std::string& device)
        : dir_(dir), sampling_(sampling), model_(load_motion_model(dir, device)) {}

    std::vector<JointSequence> generate(const std::vector<std::string>& prompts, const std::vector<uint64_t>& seeds,
                                        int frames) override {
        SampleOptions o = sampling_;
        o.frames = frames;
        o.seeds = seeds;
        std::vector<JointSequence> out;
        for (const FeatureMatrix& f : sample_motions(*model_, prompts, o)) out.push_back(recover_from_ric(f));
        return out;
    }

    nlohmann::json describe() const override {
        return {{"kind", "diffusion"}, {"model", dir_}, {"training_step", model_->meta.value("training", nlohmann::json::object()).value("step", 0)},
                {"sampler", sampling_.sampler}, {"steps", sampling_.sampler == "ddpm" ? model_->schedule.steps : sampling_.steps},
                {"guidance", sampling_.guidance}, {"eta", sampling_.eta}};
    }

private:
    std::string dir_;
    SampleOptions sampling_;
    std::unique_ptr<MotionModel> model_;
};

// Joint positions at time t * factor of the source for every output frame, linearly interpolated (20 fps).
JointSequence time_warp(const JointSequence& m, double factor) {
    const int frames = std::max(1, static_cast<int>(std::floor((m.num_frames - 1) / factor)) + 1);
    JointSequence out(frames, m.num_joints, m.fps);
    for (int f = 0; f < frames; ++f) {
        const double s = std::min(f * factor, static_cast<double>(m.num_frames - 1));
        const int a = static_cast<int>(std::floor(s));
        const int b = std::min(a + 1, m.num_frames - 1);
        const double w = s - a;
        for (int j = 0; j < m.num_joints; ++j) out.at(f, j) = (1 - w) * m.at(a, j) + w * m.at(b, j);
    }
    return out;
}

JointSequence crop(const JointSequence& m, int start, int frames) {
    JointSequence out(frames, m.num_joints, m.fps);
    std::copy(m.positions.begin() + static_cast<std::ptrdiff_t>(start) * m.num_joints,
              m.positions.begin() + static_cast<std::ptrdiff_t>(start + frames) * m.num_joints, out.positions.begin());
    return out;
}

std::string default_vocab() {
    if (const char* env = std::getenv("T2IMU_VOCAB"); env && std::filesystem::exists(env)) return env;
    return "cache/text/glove-100k.safetensors";
}

class RetrievalSource : public MotionSource {
public:
    RetrievalSource(const std::string& dataset, const std::string& vocab)
        : dataset_(dataset), vocab_(WordVectors::load(vocab.empty() ? default_vocab() : vocab)), sif_(vocab_, 1e-4),
          clips_(Hml3dDataset(dataset, "train").clips()) {
        if (clips_.empty()) throw Error(dataset, "train split", "at least one clip to retrieve");
        for (const MotionClip& c : clips_) {
            std::vector<Eigen::VectorXd> e;
            for (const CaptionLine& l : c.captions) e.push_back(sif_.embed(l.caption));
            caption_embeddings_.push_back(std::move(e));
        }
    }

    std::vector<JointSequence> generate(const std::vector<std::string>& prompts, const std::vector<uint64_t>& seeds,
                                        int frames) override {
        if (seeds.size() != prompts.size()) throw Error("retrieval", "seeds", "one per prompt");
        std::vector<JointSequence> out;
        for (size_t i = 0; i < prompts.size(); ++i) {
            std::mt19937_64 rng(seeds[i]);
            const std::vector<size_t> best = nearest_clips(prompts[i]);
            const size_t pick = best[std::uniform_int_distribution<size_t>(0, best.size() - 1)(rng)];
            const double factor = std::uniform_real_distribution<double>(1 - kRetrievalWarp, 1 + kRetrievalWarp)(rng);
            const JointSequence warped = time_warp(recover_from_ric(clips_[pick].features), factor);
            const int n = std::min(frames, warped.num_frames);
            const int start = std::uniform_int_distribution<int>(0, warped.num_frames - n)(rng);
            out.push_back(crop(warped, start, n));
        }
        return out;
    }

    nlohmann::json describe() const override {
        return {{"kind", "retrieval"}, {"dataset", dataset_}, {"split", "train"}, {"clips", clips_.size()},
                {"top_k", kRetrievalTopK}, {"time_warp", kRetrievalWarp}};
    }

private:
    std::vector<size_t> nearest_clips(const std::string& prompt) const {
        const Eigen::VectorXd p = sif_.embed(prompt);
        std::vector<std::pair<double, size_t>> scored;
        for (size_t c = 0; c < clips_.size(); ++c) {
            double best = -2;
            for (const Eigen::VectorXd& e : caption_embeddings_[c]) best = std::max(best, cosine_similarity(p, e));
            scored.push_back({-best, c});  // ascending: most similar first, ties by clip order
        }
        const size_t k = std::min<size_t>(kRetrievalTopK, scored.size());
        std::partial_sort(scored.begin(), scored.begin() + static_cast<std::ptrdiff_t>(k), scored.end());
        std::vector<size_t> out;
        for (size_t i = 0; i < k; ++i) out.push_back(scored[i].second);
        return out;
    }

    std::string dataset_;
    WordVectors vocab_;
    SifEncoder sif_;
    std::vector<MotionClip> clips_;
    std::vector<std::vector<Eigen::VectorXd>> caption_embeddings_;
};

}  // namespace

std::unique_ptr<MotionSource> open_motion_source(const std::string& spec, const SampleOptions& sampling, const std::string& device,
                                                 const std::string& vocab) {
    const std::string prefix = "retrieval:";
    if (spec.rfind(prefix, 0) == 0) return std::make_unique<RetrievalSource>(spec.substr(prefix.size()), vocab);
    return std::make_unique<DiffusionSource>(spec, sampling, device);
}

}  // namespace t2imu
