// The low-data curve (pipeline/experiment.hpp's [low_data]): balanced accuracy against the number of real training
// subjects K, per arm (real only, and each synthetic source mixed in or pretrained on), over draws of subjects. Its
// type and JSON (low-data/curves.json), torch-free, so the report draws it typed.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "har/har_result.hpp"

namespace t2imu {

struct LowDataPoint {
    std::string label;          // "0", "1", ..., or "all"
    int train_subjects = 0;     // K: real subjects trained on ("all": every subject but the ones tested)
    std::vector<double> draws;  // balanced accuracy per draw of subjects
    ScoreSummary balanced_accuracy() const;
};

struct LowDataArm {
    std::string name;  // "real only", or "<source> mix" / "<source> finetune"
    std::vector<LowDataPoint> points;
    const LowDataPoint* at(const std::string& label) const;  // nullptr when the arm has no such K
};

struct LowDataCurve {
    std::string real_set;
    std::vector<std::string> classes;
    std::vector<std::string> labels;  // the K labels in order, the x axis
    std::vector<LowDataArm> arms;
};

// {"low_data_curves": [{real_set, classes, labels, arms: [{name, points: [{label, train_subjects, draws, mean,
// sd}]}]}]}
nlohmann::json low_data_curves_json(const std::vector<LowDataCurve>& curves);
std::vector<LowDataCurve> parse_low_data_curves(const nlohmann::json& doc, const std::string& path);
bool is_low_data_curves(const nlohmann::json& doc);

// A point from a har_result_json of draws: each run's balanced accuracy, K from the runs' drawn subjects.
LowDataPoint low_data_point(const HarResult& draws, const std::string& label);

}  // namespace t2imu
