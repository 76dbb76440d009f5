// Confusion tables of the motion activity classifier (motion/motion_activity.hpp): the true or prompted activity
// (rows) against the activity a motion shows (columns), from leave-one-subject-out over the classifier's own
// reference clips or from the kept motions of a synthesis folder (t2imu synth's jobs/ and motions/).
#pragma once
#include <string>
#include <vector>

#include "motion/motion_activity.hpp"

namespace t2imu {

struct ActivityConfusion {
    std::vector<std::string> rows;          // true (reference) or prompted (synthesis) activities
    std::vector<std::string> expected;      // per row, the column that is right for it ("" = no class: not counted)
    std::vector<std::string> columns;       // the classifier's classes
    std::vector<std::vector<long>> counts;  // [row][column]

    long right() const;  // motions in their row's expected column, over the rows that have one
    long total() const;  // motions of the rows that have an expected column
    // "truth\predicted,<columns>,recall" then one line per row; recall is empty for a row without a class.
    std::string csv() const;
};

// Leave-one-subject-out over the reference clips; `agreement` (optional) receives each clip's agreement with
// its own activity.
ActivityConfusion reference_confusion(const MotionActivityClassifier& classifier,
                                      std::vector<double>* agreement = nullptr);

// Every kept job of the synthesis folder `dir` (markers read by imu/synth_folder.hpp): the prompt's activity
// against the classifier's class for the job's motion. Error naming the folder when no job is kept.
ActivityConfusion synth_confusion(const MotionActivityClassifier& classifier, const std::string& dir);

}  // namespace t2imu
