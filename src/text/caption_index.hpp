// A model's training captions, each with the activity of the clip it describes, searched by meaning: the
// captions nearest a prompt by the cosine of their SIF embeddings (sentence_similarity.hpp; the common
// component fitted on these captions), among the captions of the activity asked.
//
// Why a model needs it (caption anchor, diffusion/text_to_motion.hpp): the text encoder of t2imu's models
// (GloVe under a small transformer, trained with the motions on a few hundred distinct captions) turns the
// captions it was trained on into features the denoiser follows, and other wordings into features it follows
// less (models/default, first draws that show their activity: 62-63 of 80 when the prompts are training captions
// of the eight classes, 37 of 80 for prompts/realworld.tsv, 26 of 80 for its paraphrases). Nearness by words
// alone is not enough: in GloVe "up" and "down", "stands" and "lies" are neighbours (the nearest caption of
// "The person climbs up a flight of stairs." is "a person walks down a flight of stairs"), so the activity chooses
// the candidates and the words choose among them.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "text/prompt_set.hpp"
#include "text/sentence_similarity.hpp"
#include "text/word_vectors.hpp"

namespace t2imu {

struct CaptionNeighbour {
    size_t index = 0;       // into CaptionIndex::captions()
    double similarity = 0;  // SIF cosine, -1..1
};

class CaptionIndex {
public:
    // captions: activity (canonical name, activity_names.hpp; "" or "other" for none) and text. A repeated
    // (activity, text) pair is kept once. At least one caption with a word of the vocabulary is needed (Error
    // naming `source` otherwise). `vectors` must outlive the index.
    CaptionIndex(const WordVectors& vectors, const std::vector<Prompt>& captions, const std::string& source);

    // The k captions of activity `activity` (canonical; shows_activity, so "stairs" takes either direction) most
    // similar to `prompt` (with `match_attributes`: among those naming the most of the prompt's attributes,
    // data/measured_captions.hpp: slowly, left, then, ...), best first (ties: the earlier caption); fewer when the
    // activity has fewer, none when it is "" or has none. Across activities the nearest caption by words is too often
    // another activity's (see above; as an anchor it cost first draws). All k share the activity of the best one, so
    // "stairs" gives one direction: a blend of up and down captions conditions a walk on the level (docs/results.md on
    // one stairs direction per anchor).
    std::vector<CaptionNeighbour> nearest(const std::string& prompt, size_t k, const std::string& activity,
                                          bool match_attributes = false) const;
    const std::vector<Prompt>& captions() const { return captions_; }

private:
    SifEncoder sif_;
    std::vector<Prompt> captions_;
    std::vector<std::vector<std::string>> named_;  // per caption: the attributes it names
    Eigen::MatrixXd unit_;  // [captions, dims]: each caption's embedding at unit length (zero rows stay zero)
};

}  // namespace t2imu
