#include "har/low_data_curve.hpp"

#include "core/error.hpp"
#include "core/json_file.hpp"

namespace t2imu {

using nlohmann::json;

ScoreSummary LowDataPoint::balanced_accuracy() const {
    HarResult r;
    for (double d : draws) {
        r.runs.emplace_back();
        r.runs.back().balanced_accuracy = d;
    }
    return score_summary(r, &HarRun::balanced_accuracy);
}

const LowDataPoint* LowDataArm::at(const std::string& label) const {
    for (const LowDataPoint& p : points)
        if (p.label == label) return &p;
    return nullptr;
}

json low_data_curves_json(const std::vector<LowDataCurve>& curves) {
    json all = json::array();
    for (const LowDataCurve& c : curves) {
        json arms = json::array();
        for (const LowDataArm& a : c.arms) {
            json points = json::array();
            for (const LowDataPoint& p : a.points) {
                const ScoreSummary s = p.balanced_accuracy();
                points.push_back({{"label", p.label},
                                  {"train_subjects", p.train_subjects},
                                  {"draws", p.draws},
                                  {"mean", s.mean},
                                  {"sd", s.sd}});
            }
            arms.push_back({{"name", a.name}, {"points", points}});
        }
        all.push_back({{"real_set", c.real_set}, {"classes", c.classes}, {"labels", c.labels}, {"arms", arms}});
    }
    return {{"low_data_curves", all}};
}

bool is_low_data_curves(const json& doc) { return doc.is_object() && doc.contains("low_data_curves"); }

namespace {

std::vector<std::string> names(const json& doc, const char* key, const std::string& path, const std::string& where) {
    std::vector<std::string> out;
    for (const json& s : json_array(doc, key, path, where)) {
        if (!s.is_string()) throw Error(path, where + "." + key, "names (strings)", s.dump());
        out.push_back(s.get<std::string>());
    }
    return out;
}

LowDataPoint read_point(const json& doc, const std::string& path, const std::string& where) {
    LowDataPoint p;
    p.label = json_string(doc, "label", path, where);
    p.train_subjects = static_cast<int>(json_count(doc, "train_subjects", path, where));
    for (const json& d : json_array(doc, "draws", path, where)) {
        if (!d.is_number()) throw Error(path, where + ".draws", "balanced accuracies", d.dump());
        p.draws.push_back(d.get<double>());
    }
    return p;
}

}  // namespace

std::vector<LowDataCurve> parse_low_data_curves(const json& doc, const std::string& path) {
    std::vector<LowDataCurve> curves;
    const json& all = json_array(doc, "low_data_curves", path);
    for (size_t i = 0; i < all.size(); ++i) {
        const std::string where = "low_data_curves." + std::to_string(i);
        LowDataCurve c;
        c.real_set = json_string(all[i], "real_set", path, where);
        c.classes = names(all[i], "classes", path, where);
        c.labels = names(all[i], "labels", path, where);
        const json& arms = json_array(all[i], "arms", path, where);
        for (size_t a = 0; a < arms.size(); ++a) {
            const std::string at = where + ".arms." + std::to_string(a);
            LowDataArm arm{json_string(arms[a], "name", path, at), {}};
            const json& points = json_array(arms[a], "points", path, at);
            for (size_t k = 0; k < points.size(); ++k)
                arm.points.push_back(read_point(points[k], path, at + ".points." + std::to_string(k)));
            c.arms.push_back(arm);
        }
        curves.push_back(c);
    }
    return curves;
}

LowDataPoint low_data_point(const HarResult& draws, const std::string& label) {
    LowDataPoint p;
    p.label = label;
    p.train_subjects = draws.runs.empty() ? 0 : static_cast<int>(draws.runs.front().train_subjects.size());
    for (const HarRun& run : draws.runs) p.draws.push_back(run.balanced_accuracy);
    return p;
}

}  // namespace t2imu
