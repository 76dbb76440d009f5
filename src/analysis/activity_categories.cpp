#include "analysis/activity_categories.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace t2imu {

const std::vector<std::string> kActivityCategories = {"Dancing", "Jumping",        "Lying",    "Running",
                                                      "Sitting", "Stair climbing", "Standing", "Walking"};

namespace {

const char* description(const std::string& category) {
    if (category == "Dancing") return "a person is dancing";
    if (category == "Jumping") return "a person is jumping";
    if (category == "Lying") return "a person is lying down";
    if (category == "Running") return "a person is running";
    if (category == "Sitting") return "a person is sitting";
    if (category == "Stair climbing") return "a person is climbing stairs";
    if (category == "Standing") return "a person is standing";
    return "a person is walking";
}

// Best category and its similarity, before the threshold.
CategoryMatch best_match(const SifEncoder& encoder, const std::vector<Eigen::VectorXd>& names,
                         const std::string& caption) {
    const Eigen::VectorXd e = encoder.embed(caption);
    CategoryMatch m{"Other", -1};
    for (size_t k = 0; k < names.size(); ++k) {
        const double s = cosine_similarity(e, names[k]);
        if (s > m.similarity) m = {kActivityCategories[k], s};
    }
    return m;
}

std::vector<Eigen::VectorXd> embed_names(const SifEncoder& encoder) {
    std::vector<Eigen::VectorXd> names;
    for (const std::string& c : kActivityCategories) names.push_back(encoder.embed(description(c)));
    return names;
}

}  // namespace

bool is_high_dynamic(const std::string& c) { return c == "Dancing" || c == "Jumping" || c == "Running"; }

ActivityCategorizer::ActivityCategorizer(const SifEncoder& encoder, double tau)
    : encoder_(encoder), tau_(tau), names_(embed_names(encoder)) {}

CategoryMatch ActivityCategorizer::categorize(const std::string& caption) const {
    CategoryMatch m = best_match(encoder_, names_, caption);
    if (m.similarity < tau_) m.category = "Other";
    return m;
}

TauCalibration calibrate_tau(const SifEncoder& encoder, const std::vector<std::string>& captions,
                             const std::vector<std::string>& labels) {
    if (captions.size() != labels.size() || captions.empty())
        throw Error("calibrate_tau", "labels", "one label per caption, at least one");
    const std::vector<Eigen::VectorXd> names = embed_names(encoder);
    std::vector<CategoryMatch> best;
    for (const std::string& c : captions) best.push_back(best_match(encoder, names, c));
    TauCalibration out;
    out.captions = captions.size();
    out.agreement = -1;
    for (int step = 0; step < 100; ++step) {
        const double tau = step / 100.0;
        size_t agree = 0;
        for (size_t i = 0; i < captions.size(); ++i)
            agree += (best[i].similarity < tau ? "Other" : best[i].category) == labels[i];
        const double a = static_cast<double>(agree) / static_cast<double>(captions.size());
        if (a > out.agreement) out.agreement = a, out.tau = tau;
    }
    return out;
}

}  // namespace t2imu
