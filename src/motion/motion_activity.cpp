#include "motion/motion_activity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

double ActivityScores::agreement(const std::string& expected) const {
    const auto b = distance.find(best);
    double d_expected = INFINITY;  // the nearest class showing `expected` ("stairs": either direction)
    for (const auto& [c, d] : distance)
        if (shows_activity(c, expected)) d_expected = std::min(d_expected, d);
    if (b == distance.end() || std::isinf(d_expected)) return 1.0;
    return d_expected > 0 ? b->second / d_expected : 1.0;
}

MotionActivityClassifier::MotionActivityClassifier(std::vector<ActivityExample> reference)
    : reference_(std::move(reference)) {
    std::set<std::string> classes;
    for (const ActivityExample& e : reference_) classes.insert(e.activity);
    if (classes.size() < 2) throw Error("activity reference", "activity", "clips of at least two activities");
    classes_.assign(classes.begin(), classes.end());
    std::vector<MotionDescriptors> all;
    for (const ActivityExample& e : reference_) all.push_back(e.descriptors);
    sd_ = descriptor_moments(all).sd;
    for (double& sd : sd_)
        if (sd < 1e-9) sd = 1;  // a constant descriptor adds no distance
}

MotionActivityClassifier MotionActivityClassifier::load(const std::string& path) {
    const CsvTable t = read_csv(path);
    std::vector<ActivityExample> examples;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        ActivityExample e;
        e.activity = t.rows[r][t.column("activity")];
        e.subject = t.rows[r][t.column("subject")];
        for (size_t i = 0; i < kNumMotionDescriptors; ++i)
            e.descriptors[i] = t.number(r, t.column(kMotionDescriptorNames[i]));
        examples.push_back(e);
    }
    return MotionActivityClassifier(std::move(examples));
}

CsvTable MotionActivityClassifier::reference_table() const {
    CsvTable t;
    t.header = {"activity", "subject"};
    for (const char* name : kMotionDescriptorNames) t.header.push_back(name);
    for (const ActivityExample& e : reference_) {
        std::vector<std::string> row = {e.activity, e.subject};
        for (double v : e.descriptors) row.push_back(general_text(v, 6));
        t.rows.push_back(row);
    }
    return t;
}

ActivityScores MotionActivityClassifier::classify(const MotionDescriptors& d,
                                                  const std::string& exclude_subject) const {
    std::map<std::string, std::vector<double>> per_class;
    for (const ActivityExample& e : reference_) {
        if (!exclude_subject.empty() && e.subject == exclude_subject) continue;
        double s = 0;
        for (size_t i = 0; i < kNumMotionDescriptors; ++i) {
            const double z = (d[i] - e.descriptors[i]) / sd_[i];
            s += z * z;
        }
        per_class[e.activity].push_back(std::sqrt(s));
    }
    ActivityScores out;
    double best = INFINITY;
    for (auto& [activity, distances] : per_class) {
        const size_t k = std::min(distances.size(), static_cast<size_t>(kNeighbours));
        std::partial_sort(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(k), distances.end());
        double sum = 0;
        for (size_t i = 0; i < k; ++i) sum += distances[i];
        out.distance[activity] = sum / static_cast<double>(k);
        if (out.distance[activity] < best) best = out.distance[activity], out.best = activity;
    }
    return out;
}

std::vector<std::vector<long>> MotionActivityClassifier::leave_one_subject_out(
    std::vector<double>* own_agreement) const {
    const size_t K = classes_.size();
    std::vector<std::vector<long>> confusion(K, std::vector<long>(K, 0));
    const auto index = [&](const std::string& c) {
        return static_cast<size_t>(std::find(classes_.begin(), classes_.end(), c) - classes_.begin());
    };
    for (const ActivityExample& e : reference_) {
        const ActivityScores s = classify(e.descriptors, e.subject);
        if (s.best.empty()) continue;  // no other subject's clips
        ++confusion[index(e.activity)][index(s.best)];
        if (own_agreement) own_agreement->push_back(s.agreement(e.activity));
    }
    return confusion;
}

std::string reference_activity(const std::string& prompt_activity, const std::vector<std::string>& classes) {
    const std::string name = canonical_activity(prompt_activity);
    for (const std::string& c : classes)
        if (shows_activity(c, name)) return name;
    return "";
}

}  // namespace t2imu
