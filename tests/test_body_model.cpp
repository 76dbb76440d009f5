// The BodyModel interface through make_body: a procedural spec gives a body of that spec
// (rest frame: every joint above the floor, facing +Z, left at +X), skin points with unit outward normals at the
// that follow a rigid motion of the body exactly, refused vertices, and Kind::none and a missing SMPL file
// refused naming the field.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "body/body_model.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
BodySpec procedural(double height, double mass) {
    BodySpec s;
    s.kind = BodySpec::Kind::procedural;
    s.name = "test_body";
    s.height_m = height;
    s.mass_kg = mass;
    return s;
}
}  // namespace

TEST(BodyModel, MakesTheProceduralBodyOfTheSpec) {
    const auto body = make_body(procedural(1.80, 75));
    ASSERT_NE(body, nullptr);
    EXPECT_EQ(body->spec().name, "test_body");
    EXPECT_DOUBLE_EQ(body->spec().height_m, 1.80);
    const Joints22& j = body->rest_joints();
    // Rest frame: left at +X, the head above the pelvis, feet (toes) in front of the ankles (+Z), all above y = 0.
    EXPECT_GT(j[left_hip].x(), 0);
    EXPECT_LT(j[right_hip].x(), 0);
    EXPECT_GT(j[head].y(), j[pelvis].y());
    EXPECT_GT(j[left_foot].z(), j[left_ankle].z());
    for (const Vector3d& p : j) EXPECT_GT(p.y(), 0.0);
    EXPECT_LT(j[head].y(), 1.80);  // the head joint sits below the vertex
    // A taller body of the same build is larger.
    EXPECT_GT(make_body(procedural(2.0, 75))->rest_joints()[head].y(), j[head].y());
}

TEST(BodyModel, SurfacePointsFaceTheDocumentedDirections) {
    const auto body = make_body(procedural(1.75, 70));
    // The left thigh halfway down: around 0 = front (+Z), +pi/2 = the body's left (+X), pi = back, -pi/2 = right.
    const std::pair<double, Vector3d> expected[] = {{0, Vector3d::UnitZ()},
                                                    {M_PI / 2, Vector3d::UnitX()},
                                                    {M_PI, -Vector3d::UnitZ()},
                                                    {-M_PI / 2, -Vector3d::UnitX()}};
    const Vector3d hip = body->rest_joints()[left_hip], knee = body->rest_joints()[left_knee];
    const Vector3d axis = (knee - hip).normalized();
    for (const auto& [around, direction] : expected) {
        const SurfacePoint p = body->surface_point(left_hip, 0.5, around);
        EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
        EXPECT_GT(p.normal.dot(direction), 0.9) << around;
        // The point lies off the bone on the normal's side.
        const Vector3d on_bone = hip + (p.position - hip).dot(axis) * axis;
        EXPECT_GT((p.position - on_bone).dot(p.normal), 0.02) << around;
        EXPECT_GT((p.position - on_bone).dot(direction), 0.0) << around;
    }
}

TEST(BodyModel, AnchorsFollowARigidMotionExactly) {
    const auto body = make_body(procedural(1.75, 70));
    const RestAxes axes = rest_axes(body->rest_joints());
    const Matrix3d q = Eigen::AngleAxisd(0.8, Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
    const Vector3d t(1.5, 0.2, -0.7);
    Joints22 moved;
    for (int k = 0; k < kNumJoints; ++k) moved[k] = q * body->rest_joints()[k] + t;
    PosedFrame frame{moved, segment_rotations({moved}, axes)[0]};
    PosedFrame rest_frame{body->rest_joints(), segment_rotations({body->rest_joints()}, axes)[0]};
    for (int segment : {pelvis, left_hip, right_knee, spine3, left_elbow}) {
        const SurfacePoint p = body->surface_point(segment, 0.4, 0.3);
        const BodyAnchor a = body->anchor(segment, p);
        Vector3d position;
        Matrix3d rotation;
        body->pose_anchor(a, rest_frame, &position, &rotation);  // rest pose: where it was made
        EXPECT_LT((position - p.position).norm(), 1e-12) << kJointNames[segment];
        body->pose_anchor(a, frame, &position, &rotation);
        EXPECT_LT((position - (q * p.position + t)).norm(), 1e-12) << kJointNames[segment];
        EXPECT_LT((rotation - q).norm(), 1e-12) << kJointNames[segment];
    }
}

TEST(BodyModel, RefusesWhatItCannotMake) {
    const auto body = make_body(procedural(1.75, 70));
    EXPECT_THROW(body->vertex_point(10), Error);  // procedural bodies have no vertices
    BodySpec none;
    none.kind = BodySpec::Kind::none;
    try {
        make_body(none);
        ADD_FAILURE() << "Kind::none made a body";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--body"), std::string::npos) << e.what();
    }
    BodySpec smpl;
    smpl.kind = BodySpec::Kind::smpl;
    smpl.name = "smpl";
    smpl.smpl_path = test::scratch_dir("body_model_smpl") + "/absent.npz";
    try {
        make_body(smpl);
        ADD_FAILURE() << "a missing SMPL file made a body";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("absent.npz"), std::string::npos) << e.what();
    }
}
