// Joints -> body fitting: known poses of the procedural body are recovered; retargeting keeps directions.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "body/fitting.hpp"
#include "body/procedural_body.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

Matrix3d random_rotation(std::mt19937_64& rng, double max_deg) {
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-max_deg, max_deg);
    return AngleAxisd(u(rng) * M_PI / 180, Vector3d(n(rng), n(rng), n(rng)).normalized()).toRotationMatrix();
}
Matrix3d about(const Vector3d& axis, double deg) {
    return AngleAxisd(deg * M_PI / 180, axis.normalized()).toRotationMatrix();
}

// A pose whose segment orientations follow the anatomy the fit assumes: knees and elbows are hinges about the
// body's left-right axis, bent by 30-90 degrees (knees backwards, elbows forwards), ankles flex about the same
// axis, collars do not move against the upper trunk. Hips, shoulders, pelvis and spine turn freely.
Rotations22 anatomical_pose(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> bend(30, 90);
    Rotations22 local;
    for (Matrix3d& r : local) r = Matrix3d::Identity();
    local[pelvis] = random_rotation(rng, 60);
    for (int s : {int(spine1), int(spine2), int(spine3), int(neck)}) local[s] = random_rotation(rng, 20);
    for (int s : {int(left_hip), int(right_hip), int(left_shoulder), int(right_shoulder)})
        local[s] = random_rotation(rng, 50);
    for (int s : {int(left_knee), int(right_knee)}) local[s] = about(Vector3d::UnitX(), bend(rng));
    for (int s : {int(left_elbow), int(right_elbow)}) local[s] = about(Vector3d::UnitX(), -bend(rng));
    for (int s : {int(left_ankle), int(right_ankle)}) local[s] = about(Vector3d::UnitX(), bend(rng) - 60);
    Rotations22 global;
    for (int s = 0; s < kNumJoints; ++s)
        global[s] = kParents[s] < 0 ? local[s] : Matrix3d(global[kParents[s]] * local[s]);
    return global;
}

JointSequence to_sequence(const std::vector<Joints22>& frames) {
    JointSequence seq(static_cast<int>(frames.size()), kNumJoints, 20.0);
    for (size_t f = 0; f < frames.size(); ++f)
        for (int j = 0; j < kNumJoints; ++j) seq.at(static_cast<int>(f), j) = frames[f][j];
    return seq;
}

double angle_deg(const Matrix3d& a, const Matrix3d& b) { return AngleAxisd(a.transpose() * b).angle() * 180 / M_PI; }

}  // namespace

TEST(Fitting, RestPoseGivesIdentityRotations) {
    const ProceduralBody body(paper_bodies()[2]);
    const std::vector<Rotations22> r = segment_rotations({body.rest_joints()}, rest_axes(body.rest_joints()));
    for (int s = 0; s < kNumJoints; ++s) EXPECT_LT((r[0][s] - Matrix3d::Identity()).norm(), 1e-12) << kJointNames[s];
}

TEST(Fitting, RecoversKnownPosesOfTheProceduralBody) {
    const ProceduralBody body(paper_bodies()[5]);
    std::mt19937_64 rng(7);
    std::vector<Joints22> frames;
    std::vector<Rotations22> truth;
    for (int f = 0; f < 50; ++f) {
        truth.push_back(anatomical_pose(rng));
        frames.push_back(pose_skeleton(body.rest_joints(), truth.back(), Vector3d(0.1 * f, 0.9, -0.02 * f)));
    }
    const FittedMotion fit = fit_body(to_sequence(frames), body);
    EXPECT_DOUBLE_EQ(fit.leg_scale, 1.0);
    double worst_mm = 0;
    for (int j = 0; j < kNumJoints; ++j) worst_mm = std::max(worst_mm, fit.max_error_mm[j]);
    EXPECT_LT(worst_mm, 1.0);   // the bound
    EXPECT_LT(worst_mm, 1e-6);  // in fact exact up to rounding
    // Orientations, twist included, wherever the anatomy fixes it.
    for (size_t f = 0; f < frames.size(); ++f)
        for (int s : {int(pelvis), int(left_hip), int(right_hip), int(left_knee), int(right_knee), int(left_ankle),
                      int(right_ankle), int(left_shoulder), int(right_shoulder), int(left_elbow), int(right_elbow),
                      int(left_wrist), int(spine3)})
            EXPECT_LT(angle_deg(fit.frames[f].rotation[s], truth[f][s]), 1e-6) << kJointNames[s] << " frame " << f;
}

TEST(Fitting, StraightLimbFallsBackSmoothlyWithoutJumps) {
    // An elbow straightening from 60 degrees to 0 and bending again: the upper arm's twist must not jump.
    const ProceduralBody body(paper_bodies()[0]);
    std::vector<Joints22> frames;
    for (int f = 0; f <= 120; ++f) {
        Rotations22 g;
        for (Matrix3d& r : g) r = Matrix3d::Identity();
        const double elbow = 60 * std::fabs(std::cos(M_PI * f / 120.0));
        g[left_shoulder] = about(Vector3d(0.3, 0.2, 1), 40);
        g[left_elbow] = g[left_shoulder] * about(Vector3d::UnitX(), -elbow);
        g[left_wrist] = g[left_elbow];
        frames.push_back(pose_skeleton(body.rest_joints(), g, Vector3d(0, 0.95, 0)));
    }
    const FittedMotion fit = fit_body(to_sequence(frames), body);
    double worst_step = 0;
    for (size_t f = 1; f < frames.size(); ++f)
        worst_step = std::max(
            worst_step, angle_deg(fit.frames[f].rotation[left_shoulder], fit.frames[f - 1].rotation[left_shoulder]));
    EXPECT_LT(worst_step, 2.0);  // degrees per frame; the motion itself moves the forearm 1.5 degrees per frame
}

TEST(Fitting, RetargetingKeepsDirectionsTakesTheBodysLengthsAndScalesTheRoot) {
    const ProceduralBody tall(paper_bodies()[0]), short_body(paper_bodies()[5]);
    std::mt19937_64 rng(3);
    std::vector<Joints22> frames;
    for (int f = 0; f < 10; ++f)
        frames.push_back(pose_skeleton(tall.rest_joints(), anatomical_pose(rng), Vector3d(0.2 * f, 1.1, 0)));
    const FittedMotion fit = fit_body(to_sequence(frames), short_body);
    EXPECT_NEAR(fit.leg_scale, 1.50 / 2.00, 1e-12);  // leg length is a fixed share of stature
    for (size_t f = 0; f < frames.size(); ++f) {
        EXPECT_LT((fit.frames[f].joints[0] - fit.leg_scale * frames[f][0]).norm(), 1e-12);
        for (int j = 1; j < kNumJoints; ++j) {
            const int p = kParents[j];
            const Vector3d in = frames[f][j] - frames[f][p], out = fit.frames[f].joints[j] - fit.frames[f].joints[p];
            const Vector3d rest = short_body.rest_joints()[j] - short_body.rest_joints()[p];
            EXPECT_NEAR(out.norm(), rest.norm(), 1e-12);
            if (p != pelvis && p != spine3) {
                EXPECT_LT((out.normalized() - in.normalized()).norm(), 1e-9) << kJointNames[j];
            }
        }
    }
}
