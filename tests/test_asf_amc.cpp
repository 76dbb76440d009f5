// Acclaim ASF/AMC: a hand-written two-legged skeleton (structure, offsets, units, axes and degrees of freedom),
// forward kinematics of AMC frames checked against rotations worked out by hand (a hip flexed about its tilted
// axis, undone by the knee; a root turn), reading from files, and refused input naming the line and field.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <functional>

#include "core/error.hpp"
#include "motion/asf_amc.hpp"
#include "test_util.hpp"

using namespace t2imu;
using Eigen::Vector3d;

namespace {
const char* kAsf = R"(# hand-written test skeleton
:version 1.10
:name test
:units
  mass 1.0
  length 0.45
  angle deg
:documentation
  two femurs and one tibia
:root
   order TX TY TZ RX RY RZ
   axis XYZ
   position 0 0 0
   orientation 0 0 0
:bonedata
  begin
     id 1
     name lfemur
     direction 0 -1 0
     length 10
     axis 0 0 20  XYZ
    dof rx ry rz
    limits (-160.0 20.0)
           (-70.0 70.0)
           (-60.0 70.0)
  end
  begin
     id 2
     name ltibia
     direction 0 -1 0
     length 8
     axis 0 0 20  XYZ
    dof rx
    limits (-10.0 170.0)
  end
  begin
     id 3
     name rfemur
     direction 0 -1 0
     length 10
     axis 0 0 -20  XYZ
    dof rx ry rz
  end
:hierarchy
  begin
    root lfemur rfemur
    lfemur ltibia
  end
)";

const char* kAmc = R"(#!OML:ASF test.asf
:FULLY-SPECIFIED
:DEGREES
1
root 1 2 3 0 0 0
lfemur 90 0 0
ltibia -90
rfemur 0 0 0
2
root 1 2 3 90 0 0
lfemur 0 0 0
ltibia 0
rfemur 0 0 0
)";

}  // namespace

TEST(AsfAmc, SkeletonStructure) {
    const AsfSkeleton s = parse_asf(kAsf, "test.asf");
    // Bones breadth-first from the root, an End Site at each leaf bone's end.
    std::vector<std::string> names;
    for (const BvhJoint& j : s.structure.joints) names.push_back(j.name);
    EXPECT_EQ(names, (std::vector<std::string>{"root", "lfemur", "rfemur", "ltibia", "rfemur/end", "ltibia/end"}));
    EXPECT_EQ(s.structure.joints[3].parent, 1);
    EXPECT_TRUE(s.structure.joints[5].end_site);
    // A joint sits at its bone's start: a child is offset by its parent bone's direction x length.
    EXPECT_EQ(s.structure.joints[1].offset, Vector3d::Zero());
    EXPECT_EQ(s.structure.joints[3].offset, Vector3d(0, -10, 0));
    EXPECT_EQ(s.structure.joints[5].offset, Vector3d(0, -8, 0));
    // length 0.45: one unit is 1/0.45 inch.
    EXPECT_DOUBLE_EQ(s.metres_per_unit, 0.0254 / 0.45);
    // Degrees of freedom in AMC order: root TX TY TZ RX RY RZ -> 3 4 5 0 1 2.
    EXPECT_EQ(s.dofs[0], (std::vector<int>{3, 4, 5, 0, 1, 2}));
    EXPECT_EQ(s.dofs[3], (std::vector<int>{0}));
    EXPECT_TRUE(s.dofs[4].empty());
    // The axis C of lfemur is Rz(20 deg).
    EXPECT_NEAR(s.axis[1].angularDistance(Quat(Eigen::AngleAxisd(20 * M_PI / 180, Vector3d::UnitZ()))), 0.0, 1e-12);
}

TEST(AsfAmc, FramesPoseTheSkeletonAsWorkedOutByHand) {
    const AsfSkeleton s = parse_asf(kAsf, "test.asf");
    const std::vector<BvhPose> poses = parse_amc(kAmc, s, "test.amc");
    ASSERT_EQ(poses.size(), 2u);
    // Frame 1: root at (1, 2, 3). The hip flexes 90 deg about its local x, which the bone axis Rz(20) tilts to
    // a = (cos 20, sin 20, 0). Rodrigues for v = (0, -10, 0) at 90 deg: a x v + a (a . v) = (-10 c s, -10 s^2, -10 c).
    const std::vector<Vector3d> p = bvh_forward_kinematics(s.structure, poses[0]);
    const double c = std::cos(20 * M_PI / 180), sn = std::sin(20 * M_PI / 180);
    const Vector3d hip(1, 2, 3), knee = hip + Vector3d(-10 * c * sn, -10 * sn * sn, -10 * c);
    EXPECT_NEAR((p[1] - hip).norm(), 0.0, 1e-12);
    EXPECT_NEAR((p[3] - knee).norm(), 0.0, 1e-12);
    // The knee's -90 deg about the same axis undoes the hip: the shin hangs straight down from the knee.
    EXPECT_NEAR((p[5] - (knee + Vector3d(0, -8, 0))).norm(), 0.0, 1e-12);
    // The right leg hangs straight.
    EXPECT_NEAR((p[4] - (hip + Vector3d(0, -10, 0))).norm(), 0.0, 1e-12);
    // Frame 2: the root turned 90 deg about X carries (0, -10, 0) to (0, 0, -10).
    const std::vector<Vector3d> q = bvh_forward_kinematics(s.structure, poses[1]);
    EXPECT_NEAR((q[3] - Vector3d(1, 2, -7)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((q[5] - Vector3d(1, 2, -15)).norm(), 0.0, 1e-12);
}

TEST(AsfAmc, ReadsFiles) {
    const std::string dir = test::scratch_dir("asf_amc_files");
    std::ofstream(dir + "/t.asf") << kAsf;
    std::ofstream(dir + "/t.amc") << kAmc;
    const AsfSkeleton s = read_asf(dir + "/t.asf");
    const std::vector<BvhPose> poses = read_amc(dir + "/t.amc", s);
    ASSERT_EQ(poses.size(), 2u);
    EXPECT_EQ(poses[1].translation[0], Vector3d(1, 2, 3));
}

TEST(AsfAmc, RefusesBadAsfNamingTheLine) {
    std::string m = test::error_message([] { parse_asf(":units\n  length -1\n", "neg.asf"); });
    EXPECT_TRUE(test::contains(m, "neg.asf") && test::contains(m, "line 2") &&
                test::contains(m, "positive length unit"))
        << m;
    m = test::error_message(
        [] { parse_asf(":bonedata\n begin\n name a\n direction 0 1 0\n length 1\n end\n", "nohier.asf"); });
    EXPECT_TRUE(test::contains(m, "nohier.asf") && test::contains(m, ":hierarchy")) << m;
    std::string undefined = kAsf;
    undefined.replace(undefined.find("lfemur ltibia"), 13, "lfemur lfoot");
    m = test::error_message([&] { parse_asf(undefined, "undef.asf"); });
    EXPECT_TRUE(test::contains(m, "undef.asf") && test::contains(m, ":hierarchy") && test::contains(m, "lfoot")) << m;
    std::string bad_dof = kAsf;
    bad_dof.replace(bad_dof.find("dof rx\n"), 7, "dof rw\n");
    m = test::error_message([&] { parse_asf(bad_dof, "dof.asf"); });
    EXPECT_TRUE(test::contains(m, "dof.asf") && test::contains(m, "line") && test::contains(m, "degree of freedom") &&
                test::contains(m, "rw"))
        << m;
}

TEST(AsfAmc, RefusesBadAmcNamingTheLine) {
    const AsfSkeleton s = parse_asf(kAsf, "test.asf");
    std::string m = test::error_message([&] { parse_amc("1\nroot 1 2 3 0 0 0\nltibia -90 5\n", s, "count.amc"); });
    EXPECT_TRUE(test::contains(m, "count.amc") && test::contains(m, "line 3") &&
                test::contains(m, "1 values for ltibia"))
        << m;
    m = test::error_message([&] { parse_amc("1\nlhumerus 0 0 0\n", s, "bone.amc"); });
    EXPECT_TRUE(test::contains(m, "bone.amc") && test::contains(m, "line 2") &&
                test::contains(m, "a bone of the ASF skeleton") && test::contains(m, "lhumerus"))
        << m;
    m = test::error_message([&] { parse_amc("1\nltibia/end\n", s, "end.amc"); });  // an End Site has no values
    EXPECT_TRUE(test::contains(m, "a bone of the ASF skeleton")) << m;
    m = test::error_message([&] { parse_amc("ltibia 0\n1\n", s, "order.amc"); });
    EXPECT_TRUE(test::contains(m, "order.amc") && test::contains(m, "line 1") && test::contains(m, "frame number"))
        << m;
    m = test::error_message([&] { parse_amc("1\nltibia abc\n", s, "num.amc"); });
    EXPECT_TRUE(test::contains(m, "num.amc") && test::contains(m, "line 2") && test::contains(m, "abc")) << m;
    m = test::error_message([&] { parse_amc(":FULLY-SPECIFIED\n", s, "empty.amc"); });
    EXPECT_TRUE(test::contains(m, "empty.amc") && test::contains(m, "at least one frame")) << m;
}
