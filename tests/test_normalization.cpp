#include <gtest/gtest.h>

#include "core/npy.hpp"
#include "motion/normalization.hpp"
#include "test_util.hpp"

using namespace t2imu;

TEST(Normalization, ReproducesMdmInputWithHumanML3DStats) {
    std::string features;
    SHARED_OR_SKIP(features, "reference/humanml3d/generated/seq_synth_walk/features_263.npy");
    const std::string root = test::shared_path("reference/humanml3d/repo_files/HumanML3D");
    const FeatureStats stats = read_feature_stats(root + "/Mean.npy", root + "/Std.npy");
    const FeatureMatrix x = feature_matrix_from_array(read_npy(features), features);
    const std::string norm_path =
        test::shared_path("reference/humanml3d/generated/seq_synth_walk/features_263_normalized.npy");
    const FeatureMatrix expected = feature_matrix_from_array(read_npy(norm_path), norm_path);
    const FeatureMatrix ours = normalize_features(x, stats);
    EXPECT_LT((ours - expected).cwiseAbs().maxCoeff(), 1e-4);  // float32 reference; values reach ~100
    EXPECT_LT((denormalize_features(ours, stats) - x).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Normalization, PaddingAndMask) {
    FeatureMatrix x = FeatureMatrix::Constant(40, 263, 2.0);
    std::vector<uint8_t> mask;
    const FeatureMatrix p = pad_features(x, kMaxMotionFrames, mask);
    ASSERT_EQ(p.rows(), 196);
    EXPECT_EQ(p.topRows(40), x);
    EXPECT_EQ(p.bottomRows(156).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(std::count(mask.begin(), mask.end(), 1), 40);
    EXPECT_EQ(mask[39], 1);
    EXPECT_EQ(mask[40], 0);
    EXPECT_THROW(pad_features(FeatureMatrix::Zero(197, 263), kMaxMotionFrames, mask), Error);
}

TEST(Normalization, RefusesBadStats) {
    const std::string dir = test::scratch_dir("normalization_bad_stats");
    write_npy(dir + "/Mean.npy", NdArray::from(std::vector<float>(263, 0.f), {263}));
    std::vector<float> s(263, 1.f);
    s[7] = 0.f;
    write_npy(dir + "/Std.npy", NdArray::from(s, {263}));
    EXPECT_THROW(read_feature_stats(dir + "/Mean.npy", dir + "/Std.npy"), Error);
    write_npy(dir + "/Short.npy", NdArray::from(std::vector<float>(10, 1.f), {10}));
    EXPECT_THROW(read_feature_stats(dir + "/Mean.npy", dir + "/Short.npy"), Error);
}
