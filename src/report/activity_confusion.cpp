#include "report/activity_confusion.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "imu/synth_folder.hpp"
#include "motion/joint_sequence.hpp"
#include "motion/motion_descriptors.hpp"

namespace t2imu {

namespace {

long hits(const ActivityConfusion& t, size_t r) {
    for (size_t c = 0; c < t.columns.size(); ++c)
        if (t.columns[c] == t.expected[r]) return t.counts[r][c];
    return 0;
}

long row_total(const ActivityConfusion& t, size_t r) {
    long n = 0;
    for (long v : t.counts[r]) n += v;
    return n;
}

}  // namespace

long ActivityConfusion::right() const {
    long n = 0;
    for (size_t r = 0; r < rows.size(); ++r) n += expected[r].empty() ? 0 : hits(*this, r);
    return n;
}

long ActivityConfusion::total() const {
    long n = 0;
    for (size_t r = 0; r < rows.size(); ++r) n += expected[r].empty() ? 0 : row_total(*this, r);
    return n;
}

std::string ActivityConfusion::csv() const {
    std::string text = "truth\\predicted";
    for (const std::string& c : columns) text += "," + c;
    text += ",recall\n";
    for (size_t r = 0; r < rows.size(); ++r) {
        text += rows[r];
        for (long v : counts[r]) text += "," + std::to_string(v);
        const long n = row_total(*this, r);
        char buf[32];
        if (expected[r].empty() || n == 0)
            std::snprintf(buf, sizeof buf, ",\n");
        else
            std::snprintf(buf, sizeof buf, ",%.3f\n", static_cast<double>(hits(*this, r)) / static_cast<double>(n));
        text += buf;
    }
    return text;
}

ActivityConfusion reference_confusion(const MotionActivityClassifier& classifier, std::vector<double>* agreement) {
    ActivityConfusion t;
    t.rows = t.expected = t.columns = classifier.classes();
    t.counts = classifier.leave_one_subject_out(agreement);
    return t;
}

ActivityConfusion synth_confusion(const MotionActivityClassifier& classifier, const std::string& dir) {
    std::map<std::string, std::map<std::string, long>> counts;  // prompted -> shown -> motions
    for (const JobMarker& job : read_job_markers(dir)) {
        if (!job.kept) continue;
        const std::string file = dir + "/" + job_joints_file(job.job);
        const std::string shown =
            classifier.classify(describe_motion(joint_sequence_from_array(read_npy(file), file))).best;
        ++counts[job.activity][shown];
    }
    if (counts.empty()) throw Error(dir + "/jobs", "jobs", "at least one kept motion");
    ActivityConfusion t;
    t.columns = classifier.classes();
    for (const auto& [prompted, shown] : counts) {  // std::map: prompted activities in name order
        t.rows.push_back(prompted);
        t.expected.push_back(reference_activity(prompted, t.columns));
        t.counts.emplace_back();
        for (const std::string& c : t.columns) t.counts.back().push_back(shown.count(c) ? shown.at(c) : 0);
    }
    return t;
}

}  // namespace t2imu
