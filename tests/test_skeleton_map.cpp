// skeleton_map: every flavour is recognised from its own joint names (extra joints ignored), its units and
// position convention are the documented ones, left and right SMPL joints map to mirrored source joints, the
// in-between spine points keep SMPL's proportions, and a skeleton missing a joint is refused naming the SMPL
// joint and the closest flavour.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.hpp"
#include "motion/skeleton.hpp"
#include "motion/skeleton_map.hpp"

using namespace t2imu;

namespace {
std::vector<std::string> names_of(const SkeletonMap& m) {
    std::vector<std::string> names;
    for (const JointSource& j : m.joints) {
        names.push_back(j.from);
        if (!j.to.empty()) names.push_back(j.to);
    }
    return names;
}
const SkeletonMap& by_flavour(const std::string& flavour) {
    for (const SkeletonMap& m : skeleton_maps())
        if (m.flavour == flavour) return m;
    throw std::runtime_error("no flavour " + flavour);
}
}  // namespace

TEST(SkeletonMap, EveryFlavourIsRecognisedByItsJointNames) {
    ASSERT_EQ(skeleton_maps().size(), 6u);
    for (const SkeletonMap& m : skeleton_maps()) {
        std::vector<std::string> names = names_of(m);
        names.push_back("SomeExtraTwistBone");  // joints the map does not use are ignored
        std::reverse(names.begin(), names.end());
        EXPECT_EQ(find_skeleton_map(names, "x.bvh").flavour, m.flavour);
    }
}

TEST(SkeletonMap, UnitsAndPositionConventions) {
    // Centimetres for the BVH exports and t2imu's own; CMU ASF's "length 0.45" (1/0.45 inch); Rigify metres.
    EXPECT_DOUBLE_EQ(by_flavour("cgspeed_daz").metres_per_unit, 0.01);
    EXPECT_DOUBLE_EQ(by_flavour("bandai_namco").metres_per_unit, 0.01);
    EXPECT_DOUBLE_EQ(by_flavour("t2imu_smpl22").metres_per_unit, 0.01);
    EXPECT_DOUBLE_EQ(by_flavour("hdm05_asf_amc").metres_per_unit, 0.0254 / 0.45);
    EXPECT_DOUBLE_EQ(by_flavour("reactidle_rigify").metres_per_unit, 1.0);
    EXPECT_EQ(by_flavour("iclone_cc_base").positions, PositionChannels::add_to_offset);
    EXPECT_EQ(by_flavour("reactidle_rigify").positions, PositionChannels::root_only);
    EXPECT_EQ(by_flavour("cgspeed_daz").positions, PositionChannels::replace_offset);
    EXPECT_TRUE(by_flavour("cgspeed_daz").zero_root_first_frame_is_tpose);
    EXPECT_FALSE(by_flavour("bandai_namco").zero_root_first_frame_is_tpose);
}

TEST(SkeletonMap, OwnExportMapsEveryJointToItself) {
    const SkeletonMap& own = by_flavour("t2imu_smpl22");
    for (int j = 0; j < smpl22::kNumJoints; ++j) {
        EXPECT_EQ(own.joints[j].from, smpl22::kJointNames[j]);
        EXPECT_TRUE(own.joints[j].to.empty());
    }
}

TEST(SkeletonMap, LeftAndRightAreMirrored) {
    // An SMPL joint and its mirror (kMirror) map to different source joints with the same interpolation, and no
    // two SMPL joints share a source point.
    for (const SkeletonMap& m : skeleton_maps()) {
        std::set<std::string> used;
        for (int j = 0; j < smpl22::kNumJoints; ++j) {
            const int k = smpl22::kMirror[j];
            const JointSource &a = m.joints[j], &b = m.joints[k];
            EXPECT_DOUBLE_EQ(a.t, b.t) << m.flavour << " " << smpl22::kJointNames[j];
            if (k != j) {
                EXPECT_NE(a.from, b.from) << m.flavour << " " << smpl22::kJointNames[j];
            }
            // Each SMPL joint has its own source point.
            EXPECT_TRUE(used.insert(a.from + ">" + a.to + "@" + std::to_string(a.t)).second)
                << m.flavour << " " << smpl22::kJointNames[j];
        }
    }
}

TEST(SkeletonMap, InBetweenPointsLieOnTheSegment) {
    for (const SkeletonMap& m : skeleton_maps())
        for (const JointSource& j : m.joints) {
            if (j.to.empty()) {
                EXPECT_DOUBLE_EQ(j.t, 0.0) << m.flavour << " " << j.from;
            } else {
                EXPECT_GT(j.t, 0.0) << m.flavour << " " << j.from;
                EXPECT_LT(j.t, 1.0) << m.flavour << " " << j.from;
            }
        }
    // Bandai's Chest -> Neck holds SMPL's spine3 a quarter of the way, as the proportions in skeleton_map.cpp.
    const JointSource& spine3 = by_flavour("bandai_namco").joints[smpl22::spine3];
    EXPECT_EQ(spine3.from, "Chest");
    EXPECT_EQ(spine3.to, "Neck");
    EXPECT_DOUBLE_EQ(spine3.t, 0.25);
}

TEST(SkeletonMap, AMissingJointIsRefusedNamingItAndTheClosestFlavour) {
    std::vector<std::string> names = names_of(by_flavour("cgspeed_daz"));
    names.erase(std::remove(names.begin(), names.end(), "lShin"), names.end());
    try {
        find_skeleton_map(names, "01_01.bvh");
        ADD_FAILURE() << "a skeleton without lShin accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("01_01.bvh"), std::string::npos) << m;
        EXPECT_NE(m.find("skeleton"), std::string::npos) << m;
        EXPECT_NE(m.find("left_knee"), std::string::npos) << m;
        EXPECT_NE(m.find("closest: cgspeed_daz"), std::string::npos) << m;
        EXPECT_EQ(m.find("right_knee"), std::string::npos) << m;
    }
    EXPECT_THROW(find_skeleton_map({}, "empty.bvh"), Error);
}
