// Captions -> the paper's activity categories (its Fig. 1): the category whose name is most similar to the
// caption, or Other when even the best similarity is below a threshold tau.
//
// The paper embeds captions and names with all-MiniLM-L6-v2 and uses tau = 0.45. Our default similarity is SIF
// over GloVe (text/sentence_similarity.hpp), whose cosines sit on another scale, so tau is calibrated: the
// value that agrees best with hand-labelled captions (calibrate_tau; the shared motion capture's activity tags
// are such labels). Category names are embedded as short descriptions ("a person is walking") rather than
// bare nouns, so that both sides of the cosine are sentences. SIF weight a = 1e-4 without common-component
// removal agrees best with the shared motion capture's single-tag captions (removing the common component takes
// the activity words with it), so that is the categoriser's setting
// (docs/results.md on L_acc per activity category).
#pragma once
#include <string>
#include <vector>

#include "text/sentence_similarity.hpp"

namespace t2imu {

constexpr double kCategorySifWeight = 1e-4;  // SIF's a for categorising captions (see above)
extern const std::vector<std::string>
    kActivityCategories;  // Dancing, Jumping, Lying, Running, Sitting, Stair climbing, Standing, Walking
bool is_high_dynamic(const std::string& category);  // Dancing, Jumping, Running (the paper's grouping)

struct CategoryMatch {
    std::string category;   // one of kActivityCategories, or "Other"
    double similarity = 0;  // to the best category
};

class ActivityCategorizer {
public:
    ActivityCategorizer(const SifEncoder& encoder, double tau);
    CategoryMatch categorize(const std::string& caption) const;
    double tau() const { return tau_; }

private:
    const SifEncoder& encoder_;
    double tau_;
    std::vector<Eigen::VectorXd> names_;
};

struct TauCalibration {
    double tau = 0, agreement = 0;  // the best threshold and the share of captions it categorises as labelled
    size_t captions = 0;
};
// labels[i]: a category name or "Other". Thresholds 0.00, 0.01, ..., 0.99; the best, ties to the lowest.
TauCalibration calibrate_tau(const SifEncoder& encoder, const std::vector<std::string>& captions,
                             const std::vector<std::string>& labels);

}  // namespace t2imu
