#include "har/nn/har_training.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/json_file.hpp"
#include "core/progress.hpp"
#include "har/class_map.hpp"
#include "har/nn/deepconvlstm.hpp"

namespace t2imu {

namespace {

struct Labelled {
    const WindowSet* w;
    std::vector<size_t> index;  // windows used
    std::vector<int> label;     // class per used window
};

struct Normaliser {
    std::vector<double> mean, sd;
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
                *out++ = static_cast<float>((in[t * C + c] - n.mean[static_cast<size_t>(c)]) / n.sd[static_cast<size_t>(c)]);
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
        held_out.insert(groups.begin(), groups.begin() + static_cast<std::ptrdiff_t>(std::min(take, groups.size() - 1)));
    }
    *fit = Labelled{all.w, {}, {}};
    *val = Labelled{all.w, {}, {}};
    for (size_t k = 0; k < all.index.size(); ++k) {
        Labelled* side = held_out.count(all.w->groups[all.index[k]]) ? val : fit;
        side->index.push_back(all.index[k]);
        side->label.push_back(all.label[k]);
    }
}

HarRun fit_and_test(const Labelled& train, const Labelled& test, int classes, const HarOptions& o, uint64_t seed) {
    torch::manual_seed(seed);
    Labelled fit, val;
    split_validation(train, o.validation_share, seed, &fit, &val);
    if (fit.index.empty()) throw Error("har", "training windows", "at least one window per class to train on");
    const Normaliser norm = fit_normaliser(fit);
    DeepConvLstm model(train.w->channels, classes);
    torch::optim::Adam optimiser(model->parameters(), torch::optim::AdamOptions(o.learning_rate));
    std::vector<double> count(static_cast<size_t>(classes), 0.0);
    for (int l : fit.label) count[static_cast<size_t>(l)] += 1;
    std::vector<float> weight(static_cast<size_t>(classes));
    for (int k = 0; k < classes; ++k)
        weight[static_cast<size_t>(k)] = count[static_cast<size_t>(k)] > 0 ? static_cast<float>(fit.label.size() / (classes * count[static_cast<size_t>(k)])) : 0.f;
    const torch::Tensor class_weight = torch::tensor(weight);
    std::mt19937_64 rng(seed);
    std::vector<size_t> order(fit.index.size());
    std::iota(order.begin(), order.end(), 0);
    HarRun run;
    double best = -1, seconds = 0;
    int since_best = 0;
    std::vector<torch::Tensor> best_state;
    for (int epoch = 0; epoch < o.max_epochs && since_best < o.patience; ++epoch) {
        const auto t0 = std::chrono::steady_clock::now();
        model->train();
        std::shuffle(order.begin(), order.end(), rng);
        for (size_t start = 0; start < order.size(); start += static_cast<size_t>(o.batch)) {
            std::vector<size_t> which(order.begin() + static_cast<std::ptrdiff_t>(start),
                                      order.begin() + static_cast<std::ptrdiff_t>(std::min(order.size(), start + static_cast<size_t>(o.batch))));
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
        ++run.epochs;
        const Labelled& monitor = val.index.empty() ? fit : val;
        const double score = balanced_accuracy(confusion_matrix(monitor.label, predict(model, monitor, norm), classes));
        if (o.verbose) std::fprintf(stderr, "  epoch %d: validation balanced accuracy %.4f\n", epoch + 1, score);
        if (score > best) {
            best = score;
            since_best = 0;
            best_state.clear();
            for (const torch::Tensor& p : model->parameters()) best_state.push_back(p.detach().clone());
        } else {
            ++since_best;
        }
    }
    {
        torch::NoGradGuard no_grad;
        const auto params = model->parameters();
        for (size_t i = 0; i < params.size(); ++i) params[i].copy_(best_state[i]);
    }
    run.seconds_per_epoch = seconds / std::max(run.epochs, 1);
    run.confusion = confusion_matrix(test.label, predict(model, test, norm), classes);
    run.balanced_accuracy = balanced_accuracy(run.confusion);
    run.macro_f1 = macro_f1(run.confusion);
    return run;
}

// Class names of each side after the per-data-set maps and the coarsening rule; the shared ones, sorted.
std::vector<std::string> shared_classes(const WindowSet& a, const WindowSet& b, std::map<std::string, std::string>* rename_a,
                                        std::map<std::string, std::string>* rename_b) {
    const std::set<std::string> la(a.labels.begin(), a.labels.end()), lb(b.labels.begin(), b.labels.end());
    std::set<std::string> ca, cb;
    for (const std::string& l : la) ca.insert((*rename_a)[l] = coarsen_for(l, la, lb));
    for (const std::string& l : lb) cb.insert((*rename_b)[l] = coarsen_for(l, lb, la));
    std::vector<std::string> shared;
    std::set_intersection(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(shared));
    return shared;
}

// The windows whose class is one of `classes`; with `held_out`, only those of (or, with exclude, not of) those subjects.
Labelled labelled(const WindowSet& w, const std::vector<std::string>& classes, const std::map<std::string, std::string>& rename,
                  const std::set<std::string>* held_out = nullptr, bool exclude = false) {
    Labelled d{&w, {}, {}};
    for (size_t i = 0; i < w.size(); ++i) {
        if (held_out && (held_out->count(w.subjects[i]) > 0) == exclude) continue;
        const auto it = std::find(classes.begin(), classes.end(), rename.at(w.labels[i]));
        if (it == classes.end()) continue;
        d.index.push_back(i);
        d.label.push_back(static_cast<int>(it - classes.begin()));
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
    if (!(learning_rate > 0 && std::isfinite(learning_rate))) throw Error("har", "learning_rate", "a positive number", std::to_string(learning_rate));
    if (!(validation_share >= 0 && validation_share < 1)) throw Error("har", "validation_share", "0 to below 1", std::to_string(validation_share));
}

HarResult train_and_test(const WindowSet& train, const WindowSet& test, const HarOptions& o) {
    o.validate();
    if (train.channels != test.channels || train.length != test.length)
        throw Error("har", "windows", "the same channels and length on both sides",
                    std::to_string(train.channels) + " vs " + std::to_string(test.channels) + " channels");
    std::map<std::string, std::string> rename_train, rename_test;
    HarResult r;
    r.classes = shared_classes(train, test, &rename_train, &rename_test);
    if (r.classes.size() < 2) throw Error("har", "classes", "at least two classes both data sets have", std::to_string(r.classes.size()));
    const Labelled tr = labelled(train, r.classes, rename_train), te = labelled(test, r.classes, rename_test);
    r.train_windows = tr.index.size();
    r.test_windows = te.index.size();
    Progress progress("HAR", static_cast<size_t>(o.repeats), "trainings");
    for (int k = 0; k < o.repeats; ++k) {
        r.runs.push_back(fit_and_test(tr, te, static_cast<int>(r.classes.size()), o, o.seed + static_cast<uint64_t>(k)));
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
    if (subjects.size() < 2) throw Error("har", "subjects", "at least two subjects for --loso", std::to_string(subjects.size()));
    const size_t k = folds > 0 ? std::min(static_cast<size_t>(folds), subjects.size()) : subjects.size();
    std::vector<std::set<std::string>> held_out(k);
    size_t i = 0;
    for (const std::string& s : subjects) held_out[i++ % k].insert(s);
    Progress progress("HAR", k, "folds");
    for (size_t fold = 0; fold < k; ++fold) {
        std::string name;
        for (const std::string& s : held_out[fold]) name += (name.empty() ? "" : "+") + s;
        const Labelled tr = labelled(data, r.classes, rename, &held_out[fold], true), te = labelled(data, r.classes, rename, &held_out[fold], false);
        if (o.verbose) std::fprintf(stderr, "fold %s: %zu train, %zu test windows\n", name.c_str(), tr.index.size(), te.index.size());
        r.runs.push_back(fit_and_test(tr, te, static_cast<int>(r.classes.size()), o, o.seed + fold));
        r.run_names.push_back(name);
        r.train_windows += tr.index.size();
        r.test_windows += te.index.size();
        progress.advance();
    }
    return r;
}

ScoreSummary score_summary(const HarResult& r, double HarRun::*score) {
    ScoreSummary s;
    for (const HarRun& run : r.runs) s.runs.push_back(run.*score);
    double var = 0;
    for (double x : s.runs) s.mean += x / static_cast<double>(s.runs.size());
    for (double x : s.runs) var += (x - s.mean) * (x - s.mean);
    s.sd = s.runs.size() > 1 ? std::sqrt(var / static_cast<double>(s.runs.size() - 1)) : 0.0;
    return s;
}

nlohmann::json score_summary_json(const ScoreSummary& s) { return {{"mean", s.mean}, {"sd", s.sd}, {"runs", s.runs}}; }

std::string har_result_json(const HarResult& r, const std::string& description) {
    const auto summary = [&](double HarRun::*score) { return score_summary_json(score_summary(r, score)); };
    const size_t K = r.classes.size();
    Confusion total(K, std::vector<long>(K, 0));
    std::vector<double> recall(K, 0.0);
    std::vector<int> recall_n(K, 0);
    double epochs = 0, seconds = 0;
    for (const HarRun& run : r.runs) {
        const std::vector<double> rc = per_class_recall(run.confusion);
        for (size_t i = 0; i < K; ++i) {
            for (size_t j = 0; j < K; ++j) total[i][j] += run.confusion[i][j];
            if (!std::isnan(rc[i])) recall[i] += rc[i], ++recall_n[i];
        }
        epochs += run.epochs;
        seconds += run.seconds_per_epoch * run.epochs;
    }
    nlohmann::json per_class, records = nlohmann::json::array();
    for (size_t k = 0; k < r.runs.size(); ++k) {
        const HarRun& run = r.runs[k];
        records.push_back({{"name", k < r.run_names.size() ? r.run_names[k] : ""}, {"balanced_accuracy", run.balanced_accuracy},
                           {"macro_f1", run.macro_f1}, {"epochs", run.epochs}, {"seconds_per_epoch", run.seconds_per_epoch},
                           {"confusion", run.confusion}});
    }
    for (size_t i = 0; i < K; ++i) per_class[r.classes[i]] = recall_n[i] ? nlohmann::json(recall[i] / recall_n[i]) : nlohmann::json(nullptr);
    nlohmann::json j = {{"description", description}, {"classes", r.classes}, {"balanced_accuracy", summary(&HarRun::balanced_accuracy)},
                        {"macro_f1", summary(&HarRun::macro_f1)}, {"per_class_recall", per_class}, {"confusion", total},
                        {"run_names", r.run_names}, {"train_windows", r.train_windows}, {"test_windows", r.test_windows},
                        {"epochs_total", epochs}, {"seconds_per_epoch", epochs > 0 ? seconds / epochs : 0.0},
                        {"run_records", records}};
    return j.dump(2) + "\n";
}

HarResult read_har_result(const std::string& path) {
    const nlohmann::json j = read_json_file(path);
    HarResult r;
    for (const nlohmann::json& c : json_array(j, "classes", path)) {
        if (!c.is_string()) throw Error(path, "classes", "class names", c.dump());
        r.classes.push_back(c.get<std::string>());
    }
    r.train_windows = j.contains("train_windows") ? json_count(j, "train_windows", path) : 0;
    r.test_windows = j.contains("test_windows") ? json_count(j, "test_windows", path) : 0;
    const nlohmann::json& records = json_array(j, "run_records", path);
    for (size_t k = 0; k < records.size(); ++k) {
        const std::string where = "run_records." + std::to_string(k);
        HarRun run;
        run.balanced_accuracy = json_number(records[k], "balanced_accuracy", path, where);
        run.macro_f1 = json_number(records[k], "macro_f1", path, where);
        run.epochs = static_cast<int>(json_count(records[k], "epochs", path, where));
        run.seconds_per_epoch = json_number(records[k], "seconds_per_epoch", path, where);
        for (const nlohmann::json& row : json_array(records[k], "confusion", path, where)) {
            if (!row.is_array() || row.size() != r.classes.size()) throw Error(path, where + ".confusion", std::to_string(r.classes.size()) + " counts per row");
            run.confusion.emplace_back();
            for (const nlohmann::json& n : row) {
                if (!n.is_number_integer() || n.get<long>() < 0) throw Error(path, where + ".confusion", "whole counts from 0", n.dump());
                run.confusion.back().push_back(n.get<long>());
            }
        }
        if (run.confusion.size() != r.classes.size()) throw Error(path, where + ".confusion", std::to_string(r.classes.size()) + " rows, one per class");
        r.runs.push_back(run);
        r.run_names.push_back(json_string(records[k], "name", path, where));
    }
    return r;
}

HarResult merge_har_results(const std::vector<HarResult>& parts) {
    HarResult all;
    for (const HarResult& p : parts) {
        if (&p == &parts.front()) {
            all.classes = p.classes;
            all.train_windows = p.train_windows;
            all.test_windows = p.test_windows;
        } else if (p.classes != all.classes || p.train_windows != all.train_windows || p.test_windows != all.test_windows) {
            throw Error("har results", "classes", "the same classes and windows in every part");
        }
        all.runs.insert(all.runs.end(), p.runs.begin(), p.runs.end());
        all.run_names.insert(all.run_names.end(), p.run_names.begin(), p.run_names.end());
    }
    return all;
}

}  // namespace t2imu
