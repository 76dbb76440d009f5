#include "har/nn/har_training.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <set>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "har/class_map.hpp"
#include "har/nn/deepconvlstm.hpp"
#include "har/subject_draw.hpp"

namespace t2imu {

// Named, not anonymous: HarPretrained::State (external) holds a TrainedNet.
namespace har_training_detail {

struct Normaliser {
    std::vector<double> mean, sd;
};

// A network trained from scratch: its normalisation and its state at the best validation epoch.
struct TrainedNet {
    DeepConvLstm model{nullptr};
    Normaliser norm;
    HarRun run;
};

}  // namespace har_training_detail
using har_training_detail::Normaliser;
using har_training_detail::TrainedNet;

namespace {

struct Labelled {
    const WindowSet* w;
    std::vector<size_t> index;  // windows used
    std::vector<int> label;     // class per used window
    std::vector<int> set;       // training set per used window (train_on_sets; 0 otherwise)

    void add(size_t i, int l, int s = 0) {
        index.push_back(i);
        label.push_back(l);
        set.push_back(s);
    }
};

Normaliser fit_normaliser(const Labelled& d) {
    const size_t C = static_cast<size_t>(d.w->channels), T = static_cast<size_t>(d.w->length);
    Normaliser n{std::vector<double>(C, 0.0), std::vector<double>(C, 0.0)};
    double count = 0;
    for (size_t i : d.index)
        for (size_t t = 0; t < T; ++t)
            for (size_t c = 0; c < C; ++c) {
                const double v = d.w->data[(i * T + t) * C + c];
                n.mean[c] += v;
                n.sd[c] += v * v;
            }
    count = static_cast<double>(d.index.size() * T);
    for (size_t c = 0; c < C; ++c) {
        n.mean[c] /= count;
        n.sd[c] = std::sqrt(std::max(n.sd[c] / count - n.mean[c] * n.mean[c], 0.0));
        if (n.sd[c] < 1e-8) n.sd[c] = 1;  // a constant channel stays at 0 after centring
    }
    return n;
}

torch::Tensor windows_tensor(const Labelled& d, const std::vector<size_t>& which, const Normaliser& n) {
    const int64_t T = d.w->length, C = d.w->channels;
    torch::Tensor x = torch::empty({static_cast<int64_t>(which.size()), T, C}, torch::kFloat32);
    float* out = x.data_ptr<float>();
    for (size_t b = 0; b < which.size(); ++b) {
        const float* in = d.w->data.data() + d.index[which[b]] * static_cast<size_t>(T * C);
        for (int64_t t = 0; t < T; ++t)
            for (int64_t c = 0; c < C; ++c)
                *out++ =
                    static_cast<float>((in[t * C + c] - n.mean[static_cast<size_t>(c)]) / n.sd[static_cast<size_t>(c)]);
    }
    return x;
}

std::vector<int> predict(DeepConvLstm& model, const Labelled& d, const Normaliser& n) {
    torch::NoGradGuard no_grad;
    model->eval();
    std::vector<int> out;
    for (size_t start = 0; start < d.index.size(); start += 512) {
        std::vector<size_t> which;
        for (size_t i = start; i < std::min(d.index.size(), start + 512); ++i) which.push_back(i);
        const torch::Tensor pred = model->forward(windows_tensor(d, which, n)).argmax(1);
        for (int64_t i = 0; i < pred.size(0); ++i) out.push_back(static_cast<int>(pred[i].item<int64_t>()));
    }
    return out;
}

// Whole trials, per class, to validation until `share` of that class's trials (at least one when it has two).
void split_validation(const Labelled& all, double share, uint64_t seed, Labelled* fit, Labelled* val) {
    std::map<int, std::vector<std::string>> groups_of_class;
    std::map<std::string, int> class_of_group;
    for (size_t k = 0; k < all.index.size(); ++k) {
        const std::string& g = all.w->groups[all.index[k]];
        if (class_of_group.emplace(g, all.label[k]).second) groups_of_class[all.label[k]].push_back(g);
    }
    std::mt19937_64 rng(seed ^ 0x5eedULL);
    std::set<std::string> held_out;
    for (auto& [cls, groups] : groups_of_class) {
        std::shuffle(groups.begin(), groups.end(), rng);
        size_t take = static_cast<size_t>(std::ceil(share * static_cast<double>(groups.size())));
        if (groups.size() < 2) take = 0;
        held_out.insert(groups.begin(),
                        groups.begin() + static_cast<std::ptrdiff_t>(std::min(take, groups.size() - 1)));
    }
    *fit = Labelled{all.w, {}, {}, {}};
    *val = Labelled{all.w, {}, {}, {}};
    for (size_t k = 0; k < all.index.size(); ++k)
        (held_out.count(all.w->groups[all.index[k]]) ? val : fit)->add(all.index[k], all.label[k], all.set[k]);
}

// The class weights of the loss: inverse to class frequency in `fit` (0 for a class it lacks).
torch::Tensor class_weights(const Labelled& fit, int classes) {
    std::vector<double> count(static_cast<size_t>(classes), 0.0);
    for (int l : fit.label) count[static_cast<size_t>(l)] += 1;
    std::vector<float> weight(static_cast<size_t>(classes));
    for (int k = 0; k < classes; ++k)
        weight[static_cast<size_t>(k)] =
            count[static_cast<size_t>(k)] > 0
                ? static_cast<float>(fit.label.size() / (classes * count[static_cast<size_t>(k)]))
                : 0.f;
    return torch::tensor(weight);
}

// Positions into `fit` of one epoch's batches. Without shares: every window once, in an order shuffled per epoch.
// With shares: subject_draw.hpp's batch_counts, each set's windows taken in its own shuffled order, reshuffled when
// used up (so an epoch is bounded by the set that runs out first at its share).
class BatchOrder {
public:
    BatchOrder(const Labelled& fit, const std::vector<double>& shares, int batch, uint64_t seed)
        : shares_(shares), batch_(batch), rng_(seed), order_(fit.index.size()) {
        std::iota(order_.begin(), order_.end(), 0);
        if (shares_.empty()) return;
        pools_.resize(shares_.size());
        for (size_t k = 0; k < fit.index.size(); ++k) pools_[static_cast<size_t>(fit.set[k])].push_back(k);
        next_.assign(shares_.size(), 0);
        for (auto& pool : pools_) std::shuffle(pool.begin(), pool.end(), rng_);
    }

    std::vector<std::vector<size_t>> epoch() {
        std::vector<std::vector<size_t>> batches;
        if (shares_.empty()) {
            std::shuffle(order_.begin(), order_.end(), rng_);
            for (size_t start = 0; start < order_.size(); start += static_cast<size_t>(batch_))
                batches.emplace_back(order_.begin() + static_cast<std::ptrdiff_t>(start),
                                     order_.begin() + static_cast<std::ptrdiff_t>(std::min(
                                                          order_.size(), start + static_cast<size_t>(batch_))));
            return batches;
        }
        std::vector<size_t> sizes;
        for (const auto& pool : pools_) sizes.push_back(pool.size());
        for (const std::vector<size_t>& counts : batch_counts(shares_, sizes, batch_)) {
            batches.emplace_back();
            for (size_t i = 0; i < counts.size(); ++i)
                for (size_t n = 0; n < counts[i]; ++n) batches.back().push_back(take(i));
        }
        return batches;
    }

private:
    size_t take(size_t set) {
        if (next_[set] == pools_[set].size()) {
            std::shuffle(pools_[set].begin(), pools_[set].end(), rng_);
            next_[set] = 0;
        }
        return pools_[set][next_[set]++];
    }

    std::vector<double> shares_;
    int batch_;
    std::mt19937_64 rng_;
    std::vector<size_t> order_;
    std::vector<std::vector<size_t>> pools_;
    std::vector<size_t> next_;
};

struct StageSettings {
    double learning_rate = 1e-3;
    int max_epochs = 40;
    std::vector<double> shares;
    bool start_competes = false;  // the starting state is epoch 0's candidate (fine-tuning)
};

// Trains `model` on `fit`, early stopping on `val`'s balanced accuracy (patience o.patience), and leaves it at its
// best epoch. Fills the run's epochs and seconds per epoch.
void train_stage(DeepConvLstm& model, const Normaliser& norm, const Labelled& fit, const Labelled& val, int classes,
                 const HarOptions& o, const StageSettings& stage, uint64_t seed, HarRun* run) {
    torch::optim::Adam optimiser(model->parameters(), torch::optim::AdamOptions(stage.learning_rate));
    const torch::Tensor class_weight = class_weights(fit, classes);
    const Labelled& monitor = val.index.empty() ? fit : val;
    const auto score_now = [&] {
        return balanced_accuracy(confusion_matrix(monitor.label, predict(model, monitor, norm), classes));
    };
    BatchOrder order(fit, stage.shares, o.batch, seed);
    double best = -1, seconds = 0;
    int since_best = 0;
    std::vector<torch::Tensor> best_state;
    const auto keep_best = [&](double score) {
        if (score <= best) return ++since_best, void();
        best = score;
        since_best = 0;
        best_state.clear();
        for (const torch::Tensor& p : model->parameters()) best_state.push_back(p.detach().clone());
    };
    if (stage.start_competes) keep_best(score_now());
    run->epochs = 0;
    for (int epoch = 0; epoch < stage.max_epochs && since_best < o.patience; ++epoch) {
        const auto t0 = std::chrono::steady_clock::now();
        model->train();
        for (const std::vector<size_t>& which : order.epoch()) {
            std::vector<int64_t> y;
            for (size_t i : which) y.push_back(fit.label[i]);
            optimiser.zero_grad();
            const torch::Tensor loss = torch::nn::functional::cross_entropy(
                model->forward(windows_tensor(fit, which, norm)), torch::tensor(y),
                torch::nn::functional::CrossEntropyFuncOptions().weight(class_weight));
            loss.backward();
            optimiser.step();
        }
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++run->epochs;
        const double score = score_now();
        if (o.verbose) std::fprintf(stderr, "  epoch %d: validation balanced accuracy %.4f\n", epoch + 1, score);
        keep_best(score);
    }
    if (!best_state.empty()) {
        torch::NoGradGuard no_grad;
        const auto params = model->parameters();
        for (size_t i = 0; i < params.size(); ++i) params[i].copy_(best_state[i]);
    }
    run->seconds_per_epoch = seconds / std::max(run->epochs, 1);
}

void score_test(DeepConvLstm& model, const Normaliser& norm, const Labelled& test, int classes, HarRun* run) {
    run->confusion = confusion_matrix(test.label, predict(model, test, norm), classes);
    run->balanced_accuracy = balanced_accuracy(run->confusion);
    run->macro_f1 = macro_f1(run->confusion);
}

// From scratch with `seed`: the validation trials are split off `fit` unless `val` is given (several sets).
TrainedNet train_from_scratch(const Labelled& train, const Labelled* val_given, int classes, const HarOptions& o,
                              const std::vector<double>& shares, uint64_t seed) {
    torch::manual_seed(seed);
    Labelled fit, val;
    if (val_given)
        fit = train, val = *val_given;
    else
        split_validation(train, o.validation_share, seed, &fit, &val);
    if (fit.index.empty()) throw Error("har", "training windows", "at least one window per class to train on");
    TrainedNet net{DeepConvLstm(train.w->channels, classes), fit_normaliser(fit), {}};
    train_stage(net.model, net.norm, fit, val, classes, o, {o.learning_rate, o.max_epochs, shares, false}, seed,
                &net.run);
    return net;
}

HarRun fit_and_test(const Labelled& train, const Labelled& test, int classes, const HarOptions& o, uint64_t seed) {
    TrainedNet net = train_from_scratch(train, nullptr, classes, o, {}, seed);
    score_test(net.model, net.norm, test, classes, &net.run);
    return net.run;
}

// Class names of each side after the per-data-set maps and the coarsening rule; the shared ones, sorted.
std::vector<std::string> shared_classes(const WindowSet& a, const WindowSet& b,
                                        std::map<std::string, std::string>* rename_a,
                                        std::map<std::string, std::string>* rename_b) {
    const std::set<std::string> la(a.labels.begin(), a.labels.end()), lb(b.labels.begin(), b.labels.end());
    std::set<std::string> ca, cb;
    for (const std::string& l : la) ca.insert((*rename_a)[l] = coarsen_for(l, la, lb));
    for (const std::string& l : lb) cb.insert((*rename_b)[l] = coarsen_for(l, lb, la));
    std::vector<std::string> shared;
    std::set_intersection(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(shared));
    return shared;
}

// The windows whose class is one of `classes`; with `held_out`, only those of (or, with exclude, not of) those
// subjects.
Labelled labelled(const WindowSet& w, const std::vector<std::string>& classes,
                  const std::map<std::string, std::string>& rename, const std::set<std::string>* held_out = nullptr,
                  bool exclude = false) {
    Labelled d{&w, {}, {}, {}};
    for (size_t i = 0; i < w.size(); ++i) {
        if (held_out && (held_out->count(w.subjects[i]) > 0) == exclude) continue;
        const auto it = std::find(classes.begin(), classes.end(), rename.at(w.labels[i]));
        if (it != classes.end()) d.add(i, static_cast<int>(it - classes.begin()));
    }
    return d;
}

}  // namespace

void HarOptions::validate() const {
    if (repeats < 1) throw Error("har", "--repeats", "at least 1 training", std::to_string(repeats));
    // Fewer than one epoch would leave no trained state to test (it used to crash restoring the best epoch).
    if (max_epochs < 1) throw Error("har", "--epochs", "at least 1 epoch", std::to_string(max_epochs));
    if (patience < 1) throw Error("har", "patience", "at least 1 epoch", std::to_string(patience));
    if (batch < 1) throw Error("har", "batch", "at least 1 window", std::to_string(batch));
    if (!(learning_rate > 0 && std::isfinite(learning_rate)))
        throw Error("har", "learning_rate", "a positive number", std::to_string(learning_rate));
    if (!(validation_share >= 0 && validation_share < 1))
        throw Error("har", "validation_share", "0 to below 1", std::to_string(validation_share));
}

HarResult train_and_test(const WindowSet& train, const WindowSet& test, const HarOptions& o) {
    o.validate();
    if (train.channels != test.channels || train.length != test.length)
        throw Error("har", "windows", "the same channels and length on both sides",
                    std::to_string(train.channels) + " vs " + std::to_string(test.channels) + " channels");
    std::map<std::string, std::string> rename_train, rename_test;
    HarResult r;
    r.classes = shared_classes(train, test, &rename_train, &rename_test);
    if (r.classes.size() < 2)
        throw Error("har", "classes", "at least two classes both data sets have", std::to_string(r.classes.size()));
    const Labelled tr = labelled(train, r.classes, rename_train), te = labelled(test, r.classes, rename_test);
    r.train_windows = tr.index.size();
    r.test_windows = te.index.size();
    Progress progress("HAR", static_cast<size_t>(o.repeats), "trainings");
    for (int k = 0; k < o.repeats; ++k) {
        r.runs.push_back(
            fit_and_test(tr, te, static_cast<int>(r.classes.size()), o, o.seed + static_cast<uint64_t>(k)));
        r.run_names.push_back("seed " + std::to_string(o.seed + static_cast<uint64_t>(k)));
        progress.advance();
    }
    return r;
}

HarResult leave_one_subject_out(const WindowSet& data, const HarOptions& o, int folds) {
    o.validate();
    std::map<std::string, std::string> rename;
    for (const std::string& l : data.labels) rename[l] = l;
    const std::set<std::string> labels(data.labels.begin(), data.labels.end());
    HarResult r;
    r.classes.assign(labels.begin(), labels.end());
    const std::set<std::string> subjects(data.subjects.begin(), data.subjects.end());
    if (subjects.size() < 2)
        throw Error("har", "subjects", "at least two subjects for --loso", std::to_string(subjects.size()));
    const size_t k = folds > 0 ? std::min(static_cast<size_t>(folds), subjects.size()) : subjects.size();
    std::vector<std::set<std::string>> held_out(k);
    size_t i = 0;
    for (const std::string& s : subjects) held_out[i++ % k].insert(s);
    Progress progress("HAR", k, "folds");
    for (size_t fold = 0; fold < k; ++fold) {
        std::string name;
        for (const std::string& s : held_out[fold]) name += (name.empty() ? "" : "+") + s;
        const Labelled tr = labelled(data, r.classes, rename, &held_out[fold], true),
                       te = labelled(data, r.classes, rename, &held_out[fold], false);
        if (o.verbose)
            std::fprintf(stderr, "fold %s: %zu train, %zu test windows\n", name.c_str(), tr.index.size(),
                         te.index.size());
        r.runs.push_back(fit_and_test(tr, te, static_cast<int>(r.classes.size()), o, o.seed + fold));
        r.run_names.push_back(name);
        r.train_windows += tr.index.size();
        r.test_windows += te.index.size();
        progress.advance();
    }
    return r;
}

HarProtocol parse_har_protocol(const std::string& name, const std::string& option) {
    if (name == "mix") return HarProtocol::mix;
    if (name == "finetune") return HarProtocol::finetune;
    throw Error(option, name, "mix or finetune");
}

const char* har_protocol_name(HarProtocol protocol) { return protocol == HarProtocol::mix ? "mix" : "finetune"; }

void SeveralSetsOptions::validate(size_t sets, int batch) const {
    if (sets < 1) throw Error("har run", "--train", "at least one training set");
    check_shares(shares, sets, batch, "--train-share");
    if (test_set >= static_cast<int>(sets))
        throw Error("har", "test_set", "one of the " + std::to_string(sets) + " training sets");
    if (test_set < 0 && train_subjects != 0)
        throw Error("--train-subjects", std::to_string(train_subjects),
                    "a --train that is also the --test set to draw the subjects from");
    if (protocol == HarProtocol::finetune) {
        if (test_set < 0 || sets < 2)
            throw Error(
                "--protocol", "finetune",
                "a set to pretrain on and a --train that is also --test, with --train-subjects to fine-tune on");
    }
    validate_values();
}

void SeveralSetsOptions::validate_values() const {
    if (finetune_epochs < 0) throw Error("--finetune-epochs", std::to_string(finetune_epochs), "0 or more epochs");
    // Adam's step is about the learning rate: above 1 it would move a weight by more than its typical size per step.
    if (!(finetune_learning_rate > 0 && finetune_learning_rate <= 1))
        throw Error("--finetune-lr", std::to_string(finetune_learning_rate), "a learning rate above 0 and at most 1");
}

namespace {

// The training sets' windows side by side, labels renamed to the evaluation's classes (class_map.hpp's coarsening
// against the test set; where the test set's labels coarsen against any set, every side uses the coarse name),
// groups prefixed by the set's index so trials of two sets never merge.
struct SetsWindows {
    WindowSet all;
    std::vector<int> set_of;           // per window of `all`
    std::vector<std::string> classes;  // those the test set and every training set hold, sorted
    std::map<std::string, std::string> rename_test;
};

SetsWindows sets_windows(const std::vector<TrainingSet>& train, const WindowSet& test) {
    SetsWindows s;
    const std::set<std::string> lt(test.labels.begin(), test.labels.end());
    std::vector<std::set<std::string>> li;
    for (const TrainingSet& t : train) li.emplace_back(t.windows->labels.begin(), t.windows->labels.end());
    for (const std::string& l : lt) {
        s.rename_test[l] = l;
        for (const std::set<std::string>& other : li)
            if (coarsen_for(l, lt, other) != l) s.rename_test[l] = coarsen_for(l, lt, other);
    }
    std::set<std::string> shared;
    for (const auto& [l, c] : s.rename_test) shared.insert(c);
    s.all.length = test.length, s.all.channels = test.channels;
    for (size_t i = 0; i < train.size(); ++i) {
        const WindowSet& w = *train[i].windows;
        if (w.channels != test.channels || w.length != test.length)
            throw Error(train[i].name, "windows", "the test set's channels and length",
                        std::to_string(w.channels) + " channels");
        std::map<std::string, std::string> rename;
        std::set<std::string> mine;
        for (const std::string& l : li[i]) {
            std::string c = coarsen_for(l, li[i], lt);
            if (s.rename_test.count(c)) c = s.rename_test[c];
            mine.insert(rename[l] = c);
        }
        std::set<std::string> keep;
        std::set_intersection(shared.begin(), shared.end(), mine.begin(), mine.end(), std::inserter(keep, keep.end()));
        shared = keep;
        s.all.data.insert(s.all.data.end(), w.data.begin(), w.data.end());
        for (size_t j = 0; j < w.size(); ++j) {
            s.all.labels.push_back(rename[w.labels[j]]);
            s.all.subjects.push_back(w.subjects[j]);
            s.all.groups.push_back(std::to_string(i) + ":" + w.groups[j]);
            s.set_of.push_back(static_cast<int>(i));
        }
    }
    s.classes.assign(shared.begin(), shared.end());
    if (s.classes.size() < 2)
        throw Error("har", "classes", "at least two classes every data set has", std::to_string(s.classes.size()));
    return s;
}

// The windows of `s` whose set and subject `take` accepts, with their class.
template <class Take>
Labelled pick_windows(const SetsWindows& s, const Take& take) {
    Labelled d{&s.all, {}, {}, {}};
    for (size_t i = 0; i < s.all.size(); ++i) {
        const auto it = std::find(s.classes.begin(), s.classes.end(), s.all.labels[i]);
        if (it != s.classes.end() && take(s.set_of[i], s.all.subjects[i]))
            d.add(i, static_cast<int>(it - s.classes.begin()), s.set_of[i]);
    }
    return d;
}

Labelled joined_windows(const Labelled& a, const Labelled& b) {
    Labelled d = a;
    for (size_t k = 0; k < b.index.size(); ++k) d.add(b.index[k], b.label[k], b.set[k]);
    return d;
}

std::vector<size_t> windows_per_set(const Labelled& d, size_t sets) {
    std::vector<size_t> n(sets, 0);
    for (int s : d.set) ++n[static_cast<size_t>(s)];
    return n;
}

}  // namespace

struct HarPretrained::State {
    TrainedNet net;
    std::vector<std::string> sets, classes;
    uint64_t seed = 0;
};
HarPretrained::HarPretrained() = default;
HarPretrained::~HarPretrained() = default;

namespace {

// The pretrained network of `names` at `seed`: the one `keep` holds, or trained now (and kept there).
const TrainedNet& pretrained_net(const Labelled& others, const std::vector<std::string>& names,
                                 const std::vector<std::string>& classes, const HarOptions& o, HarPretrained* keep,
                                 TrainedNet* local) {
    if (keep && keep->state) {
        if (keep->state->sets != names || keep->state->classes != classes || keep->state->seed != o.seed)
            throw Error("har", "pretrained", "a network pretrained on the same sets, classes and seed");
        return keep->state->net;
    }
    *local = train_from_scratch(others, nullptr, static_cast<int>(classes.size()), o, {}, o.seed);
    if (!keep) return *local;
    keep->state = std::make_unique<HarPretrained::State>(HarPretrained::State{*local, names, classes, o.seed});
    return keep->state->net;
}

}  // namespace

HarResult train_on_sets(const std::vector<TrainingSet>& train, const WindowSet& test, const HarOptions& o,
                        const SeveralSetsOptions& m, HarPretrained* keep, const HarCheckpoint* checkpoint) {
    o.validate();
    m.validate(train.size(), o.batch);
    if (m.test_set >= 0 && train[static_cast<size_t>(m.test_set)].windows != &test)
        throw Error("har", "test_set", "the training set that is also the test set");
    std::vector<std::vector<std::string>> subjects;
    std::vector<std::string> names;
    for (const TrainingSet& t : train) subjects.push_back(t.windows->subjects), names.push_back(t.name);
    check_subject_split(subjects, names, test.subjects, m.test_set, m.train_subjects);
    const SetsWindows s = sets_windows(train, test);
    const int classes = static_cast<int>(s.classes.size());
    HarResult r;
    r.classes = s.classes;
    for (const TrainingSet& t : train) r.training_sets.push_back(t.name);
    r.shares = m.shares;
    r.protocol = har_protocol_name(m.protocol);
    if (m.protocol == HarProtocol::finetune)
        r.finetune_epochs = m.finetune_epochs, r.finetune_learning_rate = m.finetune_learning_rate;
    std::vector<std::vector<std::string>> draws(
        static_cast<size_t>(o.repeats));  // drawn now: a refusal comes before any training
    if (m.test_set >= 0)
        for (int k = 0; k < o.repeats; ++k)
            draws[static_cast<size_t>(k)] = draw_subjects(test.subjects, m.train_subjects, o.seed, k);
    const Labelled others = pick_windows(s, [&](int set, const std::string&) { return set != m.test_set; });
    int first = 0;
    if (checkpoint && !checkpoint->done.runs.empty()) {
        const HarResult& done = checkpoint->done;
        bool same = done.classes == r.classes && done.training_sets == r.training_sets && done.protocol == r.protocol &&
                    done.shares == r.shares && done.runs.size() <= static_cast<size_t>(o.repeats);
        for (size_t k = 0; same && k < done.runs.size(); ++k) same = done.runs[k].train_subjects == draws[k];
        if (!same)
            throw Error(
                "har", "checkpoint",
                "runs of these sets, classes, protocol, shares and draws of subjects, at most --repeats of them");
        r.runs = done.runs, r.run_names = done.run_names;
        r.train_windows = done.train_windows, r.test_windows = done.test_windows;
        first = static_cast<int>(done.runs.size());
    }
    TrainedNet local;
    const TrainedNet* pretrained = nullptr;
    if (m.protocol == HarProtocol::finetune && first < o.repeats)
        pretrained = &pretrained_net(others, r.training_sets, s.classes, o, keep, &local);
    Progress progress("HAR", static_cast<size_t>(o.repeats - first), "trainings");
    for (int k = first; k < o.repeats; ++k) {
        const uint64_t seed = o.seed + static_cast<uint64_t>(k);
        HarRun run;
        std::set<std::string> drawn;
        if (m.test_set >= 0) {
            run.train_subjects = draws[static_cast<size_t>(k)];
            drawn.insert(run.train_subjects.begin(), run.train_subjects.end());
            for (const std::string& subject : std::set<std::string>(test.subjects.begin(), test.subjects.end()))
                if (!drawn.count(subject)) run.test_subjects.push_back(subject);
        }
        const Labelled real = pick_windows(
            s, [&](int set, const std::string& subject) { return set == m.test_set && drawn.count(subject); });
        Labelled real_fit, real_val;
        split_validation(real, o.validation_share, seed, &real_fit, &real_val);
        const std::vector<size_t> per_set = windows_per_set(joined_windows(others, real), train.size());
        for (size_t i = 0; i < m.shares.size(); ++i)
            if (per_set[i] == 0)
                throw Error("--train-share", train[i].name,
                            "windows of every set that has a share (this draw has none)");
        TrainedNet net;
        if (m.protocol == HarProtocol::finetune) {
            torch::manual_seed(seed);
            net = TrainedNet{DeepConvLstm(test.channels, classes), pretrained->norm, pretrained->run};
            {
                torch::NoGradGuard no_grad;
                const auto to = net.model->parameters(), from = pretrained->model->parameters();
                for (size_t i = 0; i < to.size(); ++i) to[i].copy_(from[i]);
            }
            // With shares the fine-tuning keeps training on the other sets too, each at its share of a batch.
            if (m.finetune_epochs > 0 && !real_fit.index.empty())
                train_stage(net.model, net.norm, m.shares.empty() ? real_fit : joined_windows(others, real_fit),
                            real_val, classes, o, {m.finetune_learning_rate, m.finetune_epochs, m.shares, true}, seed,
                            &net.run);
        } else if (!real.index.empty()) {
            net = train_from_scratch(joined_windows(others, real_fit), &real_val, classes, o, m.shares, seed);
        } else {
            net = train_from_scratch(others, nullptr, classes, o, m.shares, seed);
        }
        Labelled te{&test, {}, {}, {}};
        for (size_t i = 0; i < test.size(); ++i) {
            const auto it = std::find(s.classes.begin(), s.classes.end(), s.rename_test.at(test.labels[i]));
            if (it != s.classes.end() && !drawn.count(test.subjects[i]))
                te.add(i, static_cast<int>(it - s.classes.begin()));
        }
        score_test(net.model, net.norm, te, classes, &net.run);
        net.run.train_subjects = run.train_subjects, net.run.test_subjects = run.test_subjects;
        net.run.set_windows = per_set;
        r.train_windows += others.index.size() + real.index.size();
        r.test_windows += te.index.size();
        r.runs.push_back(net.run);
        r.run_names.push_back((m.test_set >= 0 ? "draw " + std::to_string(k) + ", " : "") + "seed " +
                              std::to_string(seed));
        if (checkpoint && checkpoint->save) checkpoint->save(r);
        progress.advance();
    }
    if (m.test_set < 0)
        r.train_windows /= static_cast<size_t>(o.repeats), r.test_windows /= static_cast<size_t>(o.repeats);
    return r;
}

}  // namespace t2imu
