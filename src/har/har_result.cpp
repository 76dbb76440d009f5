#include "har/har_result.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/json_file.hpp"

namespace t2imu {

namespace {

using nlohmann::json;

std::vector<std::string> strings(const json& doc, const std::string& key, const std::string& path,
                                 const std::string& where = "") {
    std::vector<std::string> out;
    const std::string field = (where.empty() ? "" : where + ".") + key;
    for (const json& s : json_array(doc, key, path, where)) {
        if (!s.is_string()) throw Error(path, field, "names (strings)", s.dump());
        out.push_back(s.get<std::string>());
    }
    return out;
}

json run_record(const HarResult& r, size_t k) {
    const HarRun& run = r.runs[k];
    json record = {{"name", k < r.run_names.size() ? r.run_names[k] : ""},
                   {"balanced_accuracy", run.balanced_accuracy},
                   {"macro_f1", run.macro_f1},
                   {"epochs", run.epochs},
                   {"seconds_per_epoch", run.seconds_per_epoch},
                   {"confusion", run.confusion}};
    if (!run.train_subjects.empty() || !run.test_subjects.empty()) {
        record["train_subjects"] = run.train_subjects;
        record["test_subjects"] = run.test_subjects;
    }
    if (!run.set_windows.empty()) {
        json per_set = json::object();
        for (size_t i = 0; i < run.set_windows.size() && i < r.training_sets.size(); ++i)
            per_set[r.training_sets[i]] = run.set_windows[i];
        record["train_windows_per_set"] = per_set;
    }
    return record;
}

Confusion read_confusion(const json& record, size_t classes, const std::string& path, const std::string& where) {
    Confusion c;
    for (const json& row : json_array(record, "confusion", path, where)) {
        if (!row.is_array() || row.size() != classes)
            throw Error(path, where + ".confusion", std::to_string(classes) + " counts per row");
        c.emplace_back();
        for (const json& n : row) {
            if (!n.is_number_integer() || n.get<long>() < 0)
                throw Error(path, where + ".confusion", "whole counts from 0", n.dump());
            c.back().push_back(n.get<long>());
        }
    }
    if (c.size() != classes) throw Error(path, where + ".confusion", std::to_string(classes) + " rows, one per class");
    return c;
}

HarRun read_run(const json& record, const HarResult& r, const std::string& path, const std::string& where) {
    HarRun run;
    run.balanced_accuracy = json_number(record, "balanced_accuracy", path, where);
    run.macro_f1 = json_number(record, "macro_f1", path, where);
    run.epochs = static_cast<int>(json_count(record, "epochs", path, where));
    run.seconds_per_epoch = json_number(record, "seconds_per_epoch", path, where);
    run.confusion = read_confusion(record, r.classes.size(), path, where);
    if (record.contains("train_subjects")) {
        run.train_subjects = strings(record, "train_subjects", path, where);
        run.test_subjects = strings(record, "test_subjects", path, where);
    }
    if (record.contains("train_windows_per_set")) {
        const json& per_set = json_object(record, "train_windows_per_set", path, where);
        for (const std::string& set : r.training_sets)
            run.set_windows.push_back(json_count(per_set, set, path, where + ".train_windows_per_set"));
    }
    return run;
}

}  // namespace

Confusion summed_confusion(const HarResult& r) {
    const size_t K = r.classes.size();
    Confusion total(K, std::vector<long>(K, 0));
    for (const HarRun& run : r.runs)
        for (size_t i = 0; i < K; ++i)
            for (size_t j = 0; j < K; ++j) total[i][j] += run.confusion[i][j];
    return total;
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

json score_summary_json(const ScoreSummary& s) { return {{"mean", s.mean}, {"sd", s.sd}, {"runs", s.runs}}; }

std::string har_result_json(const HarResult& r, const std::string& description) {
    const auto summary = [&](double HarRun::*score) { return score_summary_json(score_summary(r, score)); };
    const size_t K = r.classes.size();
    const Confusion total = summed_confusion(r);
    std::vector<double> recall(K, 0.0);
    std::vector<int> recall_n(K, 0);
    double epochs = 0, seconds = 0;
    for (const HarRun& run : r.runs) {
        const std::vector<double> rc = per_class_recall(run.confusion);
        for (size_t i = 0; i < K; ++i)
            if (!std::isnan(rc[i])) recall[i] += rc[i], ++recall_n[i];
        epochs += run.epochs;
        seconds += run.seconds_per_epoch * run.epochs;
    }
    json per_class, records = json::array();
    for (size_t k = 0; k < r.runs.size(); ++k) records.push_back(run_record(r, k));
    for (size_t i = 0; i < K; ++i)
        per_class[r.classes[i]] = recall_n[i] ? json(recall[i] / recall_n[i]) : json(nullptr);
    json j = {{"description", description},
              {"classes", r.classes},
              {"balanced_accuracy", summary(&HarRun::balanced_accuracy)},
              {"macro_f1", summary(&HarRun::macro_f1)},
              {"per_class_recall", per_class},
              {"confusion", total},
              {"run_names", r.run_names},
              {"train_windows", r.train_windows},
              {"test_windows", r.test_windows},
              {"epochs_total", epochs},
              {"seconds_per_epoch", epochs > 0 ? seconds / epochs : 0.0}};
    if (!r.training_sets.empty()) {
        j["training_sets"] = r.training_sets;
        j["shares"] = r.shares;
        j["protocol"] = r.protocol;
        if (r.protocol == "finetune")
            j["finetune"] = {{"epochs", r.finetune_epochs}, {"learning_rate", r.finetune_learning_rate}};
    }
    j["run_records"] = records;
    return j.dump(2) + "\n";
}

bool is_har_result(const json& doc) {
    return doc.is_object() && doc.contains("run_records") && doc.contains("classes");
}

HarResult parse_har_result(const json& j, const std::string& path) {
    HarResult r;
    r.classes = strings(j, "classes", path);
    r.train_windows = j.contains("train_windows") ? json_count(j, "train_windows", path) : 0;
    r.test_windows = j.contains("test_windows") ? json_count(j, "test_windows", path) : 0;
    if (j.contains("training_sets")) {
        r.training_sets = strings(j, "training_sets", path);
        for (const json& s : json_array(j, "shares", path)) {
            if (!s.is_number() || !(s.get<double>() > 0 && s.get<double>() <= 1))
                throw Error(path, "shares", "shares above 0, at most 1", s.dump());
            r.shares.push_back(s.get<double>());
        }
        r.protocol = json_string(j, "protocol", path);
        if (r.protocol != "mix" && r.protocol != "finetune")
            throw Error(path, "protocol", "mix or finetune", r.protocol);
        if (r.protocol == "finetune") {
            r.finetune_epochs =
                static_cast<int>(json_count(json_object(j, "finetune", path), "epochs", path, "finetune"));
            r.finetune_learning_rate = json_number(json_object(j, "finetune", path), "learning_rate", path, "finetune");
        }
    }
    const json& records = json_array(j, "run_records", path);
    for (size_t k = 0; k < records.size(); ++k) {
        const std::string where = "run_records." + std::to_string(k);
        r.runs.push_back(read_run(records[k], r, path, where));
        r.run_names.push_back(json_string(records[k], "name", path, where));
    }
    return r;
}

HarResult read_har_result(const std::string& path) { return parse_har_result(read_json_file(path), path); }

HarResult merge_har_results(const std::vector<HarResult>& parts) {
    HarResult all;
    for (const HarResult& p : parts) {
        const bool drawn = !p.runs.empty() && !p.runs.front().train_subjects.empty();
        if (&p == &parts.front()) {
            all = p;
            all.runs.clear();
            all.run_names.clear();
            all.train_windows = all.test_windows = 0;
        } else if (p.classes != all.classes || p.training_sets != all.training_sets || p.protocol != all.protocol) {
            throw Error("har results", "classes", "the same classes, training sets and protocol in every part");
        }
        if (drawn || &p == &parts.front()) {
            all.train_windows += p.train_windows;
            all.test_windows += p.test_windows;
        } else if (p.train_windows != parts.front().train_windows || p.test_windows != parts.front().test_windows) {
            throw Error("har results", "train_windows",
                        "the same windows in every part (or runs with their own subject draws)");
        }
        all.runs.insert(all.runs.end(), p.runs.begin(), p.runs.end());
        all.run_names.insert(all.run_names.end(), p.run_names.begin(), p.run_names.end());
    }
    return all;
}

}  // namespace t2imu
