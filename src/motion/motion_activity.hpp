// Which activity a motion shows, judged against captured motions: the check that a "sitting" prompt produced
// a sitting motion, for the quality filter and for the confusion of generated motions by prompt activity.
//
// A reference is a table of captured clips (activity, subject, motion_descriptors.hpp's twelve statistics),
// standardised per descriptor over the reference. Classes are far from balanced in open motion capture (our
// mocap has hundreds of walking clips and three of sitting), so a plain k-nearest-neighbour vote would drown
// the small classes; instead each class c scores by d_c, the mean distance to its k nearest clips (k = 5, or
// all of a smaller class), and the motion is the class with the smallest d_c. Agreement with an expected class
// e is d_best / d_e in (0, 1]: 1 when e is the nearest class, small when e is far from what the motion shows.
//
// Reference CSV: activity,subject,<descriptor names>, one row per clip (models/motion-activity.csv is made by
// `t2imu motion activity --dataset cache/dataset --save-reference`).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "motion/motion_descriptors.hpp"

namespace t2imu {

struct ActivityExample {
    std::string activity, subject;
    MotionDescriptors descriptors;
};

struct ActivityScores {
    std::string best;
    std::map<std::string, double> distance;  // d_c per class (standardised units)
    // d_best / d_expected, d_expected of the nearest class showing `expected` (activity_names.hpp's
    // shows_activity); 1 when no class shows it.
    double agreement(const std::string& expected) const;
};

class MotionActivityClassifier {
public:
    static constexpr int kNeighbours = 5;

    explicit MotionActivityClassifier(std::vector<ActivityExample> reference);
    static MotionActivityClassifier load(const std::string& csv_path);
    CsvTable reference_table() const;

    const std::vector<std::string>& classes() const { return classes_; }
    // `exclude_subject`: leave that subject's clips out (for leave-one-subject-out validation).
    ActivityScores classify(const MotionDescriptors& d, const std::string& exclude_subject = "") const;
    // Every reference clip classified with its own subject left out: rows = true class, columns = predicted,
    // in classes() order. And each clip's agreement with its own class, for thresholds.
    std::vector<std::vector<long>> leave_one_subject_out(std::vector<double>* own_agreement = nullptr) const;

private:
    std::vector<ActivityExample> reference_;
    std::vector<std::string> classes_;
    MotionDescriptors sd_{};  // per descriptor over the reference: distances are in these units
};

// The canonical name (activity_names.hpp) of a prompt-set activity when the classifier has a class showing it
// (jogging -> running; stairs_up_down -> stairs, shown by stairs_up or stairs_down); "" when it has none.
std::string reference_activity(const std::string& prompt_activity, const std::vector<std::string>& classes);

}  // namespace t2imu
