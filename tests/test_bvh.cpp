// BVH parsing and forward kinematics against positions worked out by hand, and malformed files.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "motion/bvh.hpp"

using namespace t2imu;

namespace {

// A root with an arm of two 10-unit bones along +X. Frame 0: rest. Frame 1: root moved to (1,2,3) and turned
// 90 degrees about Y; the elbow bent 90 degrees about Z.
const char* kArm = R"(HIERARCHY
ROOT root
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Yrotation Xrotation Zrotation
  JOINT elbow
  {
    OFFSET 10 0 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    End Site
    {
      OFFSET 10 0 0
    }
  }
}
MOTION
Frames: 2
Frame Time: 0.05
0 0 0 0 0 0 0 0 0
1 2 3 90 0 0 90 0 0
)";

}  // namespace

TEST(Bvh, ForwardKinematicsMatchesHandComputedPositions) {
    const BvhMotion m = parse_bvh(kArm, "arm.bvh");
    ASSERT_EQ(m.joints.size(), 3u);
    EXPECT_EQ(m.num_channels, 9);
    EXPECT_EQ(m.joints[2].name, "elbow/end");
    auto rest = bvh_forward_kinematics(m, bvh_pose(m, 0));
    EXPECT_LT((rest[1] - Eigen::Vector3d(10, 0, 0)).norm(), 1e-12);
    EXPECT_LT((rest[2] - Eigen::Vector3d(20, 0, 0)).norm(), 1e-12);
    // Root yaw +90 about Y takes +X to -Z; the elbow's +90 about Z takes the forearm's +X to +Y (Y is unmoved by
    // the yaw).
    auto moved = bvh_forward_kinematics(m, bvh_pose(m, 1));
    EXPECT_LT((moved[0] - Eigen::Vector3d(1, 2, 3)).norm(), 1e-12);
    EXPECT_LT((moved[1] - Eigen::Vector3d(1, 2, -7)).norm(), 1e-12);
    EXPECT_LT((moved[2] - Eigen::Vector3d(1, 12, -7)).norm(), 1e-12);
}

TEST(Bvh, RotationOrderFollowsTheChannelOrder) {
    // X then Y (R = Rx Ry) differs from Y then X for the same angles.
    auto tip = [](const char* order) {
        std::string text = std::string("HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 2 ") + order +
                           "\n End Site\n {\n  OFFSET 0 0 1\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n90 90\n";
        const BvhMotion m = parse_bvh(text, "order.bvh");
        return bvh_forward_kinematics(m, bvh_pose(m, 0))[1];
    };
    // Rx(90) Ry(90) (0,0,1): Ry takes +Z to +X, Rx leaves +X: (1,0,0).
    EXPECT_LT((tip("Xrotation Yrotation") - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
    // Ry(90) Rx(90) (0,0,1): Rx takes +Z to -Y, Ry leaves -Y: (0,-1,0).
    EXPECT_LT((tip("Yrotation Xrotation") - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
}

TEST(Bvh, FormatThenParseRoundTrip) {
    const BvhMotion m = parse_bvh(kArm, "arm.bvh");
    const BvhMotion again = parse_bvh(format_bvh(m), "again.bvh");
    ASSERT_EQ(again.joints.size(), m.joints.size());
    EXPECT_EQ(again.values, m.values);
    EXPECT_DOUBLE_EQ(again.frame_time, m.frame_time);
    for (size_t j = 0; j < m.joints.size(); ++j) EXPECT_EQ(again.joints[j].parent, m.joints[j].parent);
}

TEST(Bvh, CrlfLineEndsParse) {
    std::string text = kArm;
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(parse_bvh(crlf, "crlf.bvh").values, parse_bvh(text, "lf.bvh").values);
}

TEST(Bvh, MalformedFilesAreRefusedWithTheLine) {
    const std::string good = kArm;
    const std::string truncated = good.substr(0, good.size() - 8);
    const std::string extra = good + "5\n";
    std::string bad_channel = good;
    bad_channel.replace(bad_channel.find("Zrotation Xrotation"), 9, "Wrotation");
    std::string bad_number = good;
    bad_number.replace(bad_number.rfind("90"), 2, "9x");
    for (const std::string& text : {truncated, extra, bad_channel, bad_number, std::string("garbage"), std::string()}) {
        try {
            parse_bvh(text, "bad.bvh");
            ADD_FAILURE() << "accepted:\n" << text;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind("bad.bvh: ", 0), 0u) << e.what();
        }
    }
}

TEST(Bvh, PositionChannelsReplaceAddToOrOnlyMoveTheRootAsTheExporterMeant) {
    // Root at OFFSET (0, 1, 0) with channels (0.1, 0, 0); its child at OFFSET (0, 0.5, 0) with channels
    // (0, 0.52, 0) (a child's channels repeating its OFFSET up to a 2 cm drift, as ReActIdle's thighs).
    const std::string text =
        "HIERARCHY\nROOT r\n{\n OFFSET 0 1 0\n CHANNELS 3 Xposition Yposition Zposition\n JOINT c\n {\n  OFFSET 0 0.5 "
        "0\n"
        "  CHANNELS 3 Xposition Yposition Zposition\n  End Site\n  {\n   OFFSET 0 0.1 0\n  }\n }\n}\n"
        "MOTION\nFrames: 1\nFrame Time: 0.05\n0.1 0 0 0 0.52 0\n";
    const BvhMotion m = parse_bvh(text, "channels.bvh");
    auto child = [&](PositionChannels c) { return bvh_forward_kinematics(m, bvh_pose(m, 0, c))[1]; };
    EXPECT_LT((child(PositionChannels::replace_offset) - Eigen::Vector3d(0.1, 0.52, 0)).norm(), 1e-12);
    EXPECT_LT((child(PositionChannels::add_to_offset) - Eigen::Vector3d(0.1, 2.02, 0)).norm(), 1e-12);
    EXPECT_LT((child(PositionChannels::root_only) - Eigen::Vector3d(0.1, 1.5, 0)).norm(), 1e-12);
}
