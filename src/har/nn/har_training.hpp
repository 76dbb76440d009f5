// Train DeepConvLSTM on one set of windows and test it on another: the paper's synthetic-to-real experiment
// (and leave-one-subject-out real-to-real as its ceiling). Torch stays inside the .cpp.
//
// Training: per-channel normalisation fitted on the training windows only; 0.15 of the training trials
// (whole trials, stratified by class, so windows of one trial never sit on both sides) held out for early
// stopping on balanced accuracy (patience 5 epochs, at most `max_epochs`); class-weighted cross-entropy
// (weights inverse to class frequency) so a rare class counts as much as a frequent one; Adam, learning rate
// 1e-3, batch 64. Adam rather than the paper's RMSProp: the same per-parameter step scaling plus momentum,
// and the default of HAR re-implementations; the choice changes results by less than run-to-run variation.
// Several training sets (train_on_sets): one normalisation over all of them; the validation trials come from the set
// that is also the test set where there is one (the target domain), so the other sets train in full.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "har/har_result.hpp"
#include "har/windowing.hpp"

namespace t2imu {

struct HarOptions {
    int repeats = 10;
    uint64_t seed = 0;
    int max_epochs = 40, patience = 5, batch = 64;
    double learning_rate = 1e-3, validation_share = 0.15;
    bool verbose = false;

    // Throws Error naming the option (--repeats, --epochs...) for a value out of range; the trainings call it.
    void validate() const;
};

// The classes both sets share (class_map.hpp rules), then `repeats` trainings with seeds seed, seed+1, ...
HarResult train_and_test(const WindowSet& train, const WindowSet& test, const HarOptions& options);
// One fold per subject: train on the others, test on that subject (each fold trained once). With folds > 0,
// subjects are dealt (sorted by name, round robin) into that many folds instead: leave-k-subjects-out, for
// data sets with many subjects where one training per subject costs too much.
HarResult leave_one_subject_out(const WindowSet& data, const HarOptions& options, int folds = 0);

// Training on several sets (synthetic and a few real subjects): mix trains once on all of them together; finetune
// trains on every set but the one that is also the test set (seed --seed, once for all repeats), then goes on training
// on that set's drawn subjects with its own learning rate and at most `finetune_epochs` (early stopping; the
// pretrained state competes as epoch 0). Zero fine-tuning epochs is plain training on the other sets.
enum class HarProtocol { mix, finetune };
HarProtocol parse_har_protocol(const std::string& name, const std::string& option);  // "mix" or "finetune"
const char* har_protocol_name(HarProtocol protocol);

struct TrainingSet {
    const WindowSet* windows = nullptr;
    std::string name;  // its dataset folder, as the result records it
};

struct SeveralSetsOptions {
    HarProtocol protocol = HarProtocol::mix;
    // Of each batch, one per training set. mix: empty = in proportion to their windows; finetune: of each fine-tuning
    // batch (the other sets keep a share while the drawn subjects are learnt), empty = the drawn subjects alone.
    std::vector<double> shares;
    int test_set = -1;       // the training set that is also the test set (its subjects are drawn); -1: none
    int train_subjects = 0;  // with test_set: subjects drawn from it for each repeat (seed --seed, the repeat)
    int finetune_epochs = 20;
    double finetune_learning_rate = 3e-4;

    // Throws Error naming the option (--train-share, --protocol, --finetune-epochs, ...) for a bad combination.
    void validate(size_t sets, int batch) const;
    // The fine-tuning's epochs and learning rate alone, in range whatever the mode (the CLI checks them always).
    void validate_values() const;
};

// The finetune protocol's pretrained network, kept between calls (another number of subjects) so the other sets
// are trained on once; it remembers its sets and seed and is refused for others.
class HarPretrained {
public:
    HarPretrained();
    ~HarPretrained();
    struct State;
    std::unique_ptr<State> state;
};

// A long series of trainings that a stop should not lose: the result so far is handed to `save` after each run, and a
// call given that result back (`done`) trains only the runs after it. Each run draws from its own seed, so the resumed
// series is the uninterrupted one.
struct HarCheckpoint {
    HarResult done;  // no runs: from the first
    std::function<void(const HarResult&)> save;
};

// `repeats` trainings (seeds seed, seed+1, ...), each with its own draw of subjects when test_set >= 0; the test is
// `test` (with test_set: the same WindowSet as that training set) less the drawn subjects. Classes: those the test
// set and every training set share. Refuses a subject that is both trained and tested on.
HarResult train_on_sets(const std::vector<TrainingSet>& train, const WindowSet& test, const HarOptions& options,
                        const SeveralSetsOptions& sets, HarPretrained* pretrained = nullptr,
                        const HarCheckpoint* checkpoint = nullptr);

}  // namespace t2imu
