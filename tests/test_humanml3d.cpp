// HumanML3D representation against vectors made with the official code (shared/data/reference/humanml3d).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/npy.hpp"
#include "motion/humanml3d.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

using namespace t2imu;

namespace {

const char* kSequences[] = {"seq_012314_new_joints", "seq_000021_raw", "seq_synth_walk", "seq_synth_turn"};

std::string ref(const std::string& seq, const std::string& file) {
    return test::shared_path("reference/humanml3d/generated/" + seq + "/" + file);
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
    EXPECT_EQ(a.size(), b.size());
    double m = 0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
    return m;
}

std::vector<double> flat(const JointSequence& s) {
    std::vector<double> v;
    for (const auto& p : s.positions) v.insert(v.end(), {p.x(), p.y(), p.z()});
    return v;
}

std::vector<double> flat(const FeatureMatrix& m) { return std::vector<double>(m.data(), m.data() + m.size()); }

std::vector<double> flat(const std::vector<PoseQuats>& q) {
    std::vector<double> v;
    for (const auto& frame : q)
        for (const Quat& x : frame) v.insert(v.end(), {x.w(), x.x(), x.y(), x.z()});
    return v;
}

JointSequence load_joints(const std::string& path) { return joint_sequence_from_array(read_npy(path), path); }

}  // namespace

class HumanML3DReference : public ::testing::TestWithParam<const char*> {};

TEST_P(HumanML3DReference, ProcessFileMatchesEveryIntermediate) {
    std::string input;
    SHARED_OR_SKIP(input, "reference/humanml3d/generated/" + std::string(GetParam()) + "/input_joints.npy");
    const ProcessFileResult r = process_file(load_joints(input));
    const std::string seq = GetParam();
    struct Check {
        const char* file;
        std::vector<double> ours;
    };
    const Check checks[] = {
        {"after_uniform_skeleton.npy", flat(r.after_uniform_skeleton)},
        {"global_positions.npy", flat(r.global_positions)},
        {"local_positions_rifke.npy", flat(r.local_positions)},
        {"ik_quat_smooth.npy", flat(r.ik_quats_smooth)},
        {"features_263.npy", flat(r.features)},
    };
    for (const Check& c : checks) {
        const std::vector<double> expected = read_npy(ref(seq, c.file)).to<double>();
        std::vector<double> ours = c.ours;
        EXPECT_LT(max_abs_diff(ours, expected), 1e-5) << seq << " " << c.file;
    }
    std::vector<double> l_velocity;  // stored by NumPy in Fortran order
    for (int f = 0; f < r.l_velocity.rows(); ++f)
        l_velocity.insert(l_velocity.end(), {r.l_velocity(f, 0), r.l_velocity(f, 1)});
    EXPECT_LT(max_abs_diff(l_velocity, read_npy(ref(seq, "l_velocity.npy")).to<double>()), 1e-5) << seq;
    const std::vector<double> fwd = read_npy(ref(seq, "forward_init.npy")).to<double>();
    EXPECT_LT(max_abs_diff({r.forward_init.x(), r.forward_init.y(), r.forward_init.z()}, fwd), 1e-6);
}

TEST_P(HumanML3DReference, RecoverFromRicMatches) {
    std::string features;
    SHARED_OR_SKIP(features, "reference/humanml3d/generated/" + std::string(GetParam()) + "/features_263.npy");
    const FeatureMatrix f = feature_matrix_from_array(read_npy(features), features);
    EXPECT_LT(max_abs_diff(flat(recover_from_ric(f)), read_npy(ref(GetParam(), "recover_from_ric.npy")).to<double>()),
              1e-5);
    const RootTrajectory root = recover_root_rot_pos(f);
    std::vector<double> quat, pos;
    for (size_t t = 0; t < root.rotation.size(); ++t) {
        quat.insert(quat.end(),
                    {root.rotation[t].w(), root.rotation[t].x(), root.rotation[t].y(), root.rotation[t].z()});
        pos.insert(pos.end(), {root.position[t].x(), root.position[t].y(), root.position[t].z()});
    }
    EXPECT_LT(max_abs_diff(quat, read_npy(ref(GetParam(), "recover_root_rot_quat.npy")).to<double>()), 1e-5);
    EXPECT_LT(max_abs_diff(pos, read_npy(ref(GetParam(), "recover_root_pos.npy")).to<double>()), 1e-5);
}

TEST_P(HumanML3DReference, RecoverFromRotMatches) {
    std::string features;
    SHARED_OR_SKIP(features, "reference/humanml3d/generated/" + std::string(GetParam()) + "/features_263.npy");
    std::array<Eigen::Vector3d, 22> offsets = smpl22::kTargetOffsets;
    const JointSequence j = recover_from_rot(feature_matrix_from_array(read_npy(features), features), offsets);
    EXPECT_LT(max_abs_diff(flat(j), read_npy(ref(GetParam(), "recover_from_rot.npy")).to<double>()), 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Sequences, HumanML3DReference, ::testing::ValuesIn(kSequences));

TEST(HumanML3D, ReleasedFeaturesOf012314) {
    std::string vecs;
    SHARED_OR_SKIP(vecs, "reference/humanml3d/repo_files/HumanML3D/new_joint_vecs/012314.npy");
    const std::string joints_path = test::shared_path("reference/humanml3d/repo_files/HumanML3D/new_joints/012314.npy");
    const FeatureMatrix released = feature_matrix_from_array(read_npy(vecs), vecs);
    // The released joints are recover_from_ric of the released features.
    EXPECT_LT(max_abs_diff(flat(recover_from_ric(released)), read_npy(joints_path).to<double>()), 1e-5);
    // Features recomputed from the released joints agree with the release on rows 0-100 (the reference README
    // explains the tail: the original run had one more raw frame, which the sigma-20 smoothing sees).
    const FeatureMatrix ours = joints_to_features(load_joints(joints_path));
    EXPECT_LT(max_abs_diff(flat(FeatureMatrix(ours.topRows(101))), flat(FeatureMatrix(released.topRows(101)))), 1e-5);
}

TEST(HumanML3D, RoundTripOfFeaturesThroughJoints) {
    std::string input;
    SHARED_OR_SKIP(input, "reference/humanml3d/generated/seq_synth_turn/input_joints.npy");
    const ProcessFileResult r = process_file(load_joints(input));
    const JointSequence rec = recover_from_ric(r.features);
    // recover_from_ric gives back the canonicalised global positions of frames 0..F-2.
    double m = 0;
    for (int f = 0; f < rec.num_frames; ++f)
        for (int j = 0; j < 22; ++j)
            m = std::max(m, (rec.at(f, j) - r.global_positions.at(f, j)).cwiseAbs().maxCoeff());
    EXPECT_LT(m, 1e-6);  // the canonicalised positions are held in float32, as in the reference
}

TEST(HumanML3D, RefusesBadInput) {
    JointSequence one(1, 22, 20);
    EXPECT_THROW(process_file(one), Error);
    JointSequence nan(5, 22, 20);
    nan.at(2, 3).x() = std::nan("");
    EXPECT_THROW(process_file(nan), Error);
    FeatureMatrix wrong(4, 100);
    EXPECT_THROW(recover_from_ric(wrong), Error);
}
