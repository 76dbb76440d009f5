// SMPL-format bodies: a small model in the official array layout, made here (the real file is licensed).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "body/fitting.hpp"
#include "body/procedural_body.hpp"
#include "body/smpl_model.hpp"
#include "core/error.hpp"
#include "core/npz.hpp"
#include "imu/virtual_imu.hpp"
#include "test_util.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr int K = SmplBody::kJoints, kRing = 8, kBetas = 2, kPoseDims = 9 * (K - 1);
const int kSmplParents[K] = {-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21};

// 24 joints in a T-pose made from the procedural body (arms turned out sideways), hands beyond the wrists.
std::vector<Vector3d> t_pose_joints() {
    const ProceduralBody body(paper_bodies()[2]);
    std::vector<Vector3d> j(body.rest_joints().begin(), body.rest_joints().end());
    for (int side = 0; side < 2; ++side) {
        const double sx = side == 0 ? 1 : -1;
        const int s = side == 0 ? left_shoulder : right_shoulder;
        const Vector3d sh = j[s];
        j[s + 2] = sh + sx * Vector3d(0.31, 0, 0);  // elbow
        j[s + 4] = sh + sx * Vector3d(0.56, 0, 0);  // wrist
    }
    j.push_back(j[left_wrist] + Vector3d(0.08, 0, 0));
    j.push_back(j[right_wrist] + Vector3d(-0.08, 0, 0));
    return j;
}

// Each joint gets a ring of 8 vertices around it (radius 4 cm in a plane holding the bone), rigidly weighted
// to that joint, except ring vertex 0 of the elbows, shared 50/50 with the shoulder; J_regressor averages
// each ring, so the joints regress exactly onto themselves. Faces fan around each ring.
std::string write_test_model(const std::string& dir, std::mt19937_64& rng) {
    const std::vector<Vector3d> joints = t_pose_joints();
    const int V = K * kRing;
    std::vector<double> v(static_cast<size_t>(V) * 3), shapedirs(static_cast<size_t>(V) * 3 * kBetas);
    std::vector<double> posedirs(static_cast<size_t>(V) * 3 * kPoseDims), weights(static_cast<size_t>(V) * K, 0.0);
    std::vector<double> regressor(static_cast<size_t>(K) * V, 0.0);
    std::vector<int64_t> kintree(2 * K), faces;
    std::normal_distribution<double> n;
    for (int k = 0; k < K; ++k) {
        for (int r = 0; r < kRing; ++r) {
            const int i = k * kRing + r;
            const double a = 2 * M_PI * r / kRing;
            const Vector3d p = joints[static_cast<size_t>(k)] + 0.04 * Vector3d(std::cos(a), 0, std::sin(a));
            for (int c = 0; c < 3; ++c) v[static_cast<size_t>(3 * i + c)] = p[c];
            // beta 0 grows the body by 10 % upwards per unit; beta 1 is random.
            for (int c = 0; c < 3; ++c) {
                shapedirs[static_cast<size_t>((3 * i + c) * kBetas + 0)] = c == 1 ? 0.1 * p.y() : 0.0;
                shapedirs[static_cast<size_t>((3 * i + c) * kBetas + 1)] = 0.01 * n(rng);
                for (int d = 0; d < kPoseDims; ++d)
                    posedirs[static_cast<size_t>((3 * i + c) * kPoseDims + d)] = 1e-3 * n(rng);
            }
            weights[static_cast<size_t>(i * K + k)] = 1.0;
            regressor[static_cast<size_t>(k * V + i)] = 1.0 / kRing;
            faces.insert(faces.end(), {i, k * kRing + (r + 1) % kRing, k * kRing + (r + 2) % kRing});
        }
        kintree[static_cast<size_t>(k)] = kSmplParents[k] < 0 ? 4294967295LL : kSmplParents[k];
        kintree[static_cast<size_t>(K + k)] = k;
    }
    for (int elbow : {int(left_elbow), int(right_elbow)}) {
        const int i = elbow * kRing;
        weights[static_cast<size_t>(i * K + elbow)] = 0.5;
        weights[static_cast<size_t>(i * K + kSmplParents[elbow])] = 0.5;
    }
    const std::string path = dir + "/smpl_test.npz";
    write_npz(path, {{"v_template", NdArray::from(v, {V, 3})},
                     {"shapedirs", NdArray::from(shapedirs, {V, 3, kBetas})},
                     {"posedirs", NdArray::from(posedirs, {V, 3, kPoseDims})},
                     {"J_regressor", NdArray::from(regressor, {K, V})},
                     {"weights", NdArray::from(weights, {V, K})},
                     {"kintree_table", NdArray::from(kintree, {2, K})},
                     {"f", NdArray::from(faces, {static_cast<int64_t>(faces.size() / 3), 3})}});
    return path;
}

BodySpec smpl_spec(const std::string& path, std::vector<double> betas = {}) {
    BodySpec s;
    s.kind = BodySpec::Kind::smpl;
    s.name = "smpl";
    s.smpl_path = path;
    s.betas = std::move(betas);
    return s;
}

PosedFrame rest_frame(const BodyModel& body) {
    PosedFrame f;
    f.joints = body.rest_joints();
    for (Matrix3d& r : f.rotation) r.setIdentity();
    return f;
}

}  // namespace

TEST(SmplModel, ShapeBlendShapesAndJointRegression) {
    std::mt19937_64 rng(1);
    const std::string path = write_test_model(test::scratch_dir("smpl_shape"), rng);
    const SmplBody flat(smpl_spec(path)), tall(smpl_spec(path, {1.0}));
    // beta 0 = 1 stretches every height by 10 % (then the floor shift puts the soles back at 0).
    const double floor_flat = t_pose_joints()[0].y() - flat.rest_joints()[0].y();
    for (int j = 0; j < kNumJoints; ++j) {
        const Vector3d expect = t_pose_joints()[static_cast<size_t>(j)] - Vector3d(0, floor_flat, 0);
        EXPECT_LT((flat.rest_joints()[j] - expect).norm(), 1e-12) << kJointNames[j];
    }
    const double flat_height = flat.rest_joints()[head].y() - flat.rest_joints()[left_ankle].y();
    const double tall_height = tall.rest_joints()[head].y() - tall.rest_joints()[left_ankle].y();
    EXPECT_NEAR(tall_height / flat_height, 1.1, 1e-12);
    EXPECT_THROW(SmplBody(smpl_spec(path, {1, 2, 3})), Error);  // more betas than the model has
}

TEST(SmplModel, RigidWholeBodyMotionMovesEveryVertexRigidly) {
    std::mt19937_64 rng(2);
    const SmplBody body(smpl_spec(write_test_model(test::scratch_dir("smpl_rigid"), rng), {0.3, -1}));
    const Matrix3d r = AngleAxisd(0.7, Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
    const Vector3d t(0.4, 0.1, -2);
    PosedFrame f;
    for (int j = 0; j < kNumJoints; ++j) f.joints[j] = r * body.rest_joints()[j] + t;
    for (Matrix3d& m : f.rotation) m = r;  // every local rotation is the identity: no pose blend shapes
    const SmplBody::Matrix posed = body.posed_vertices(f);
    for (int v = 0; v < body.num_vertices(); ++v)
        EXPECT_LT((posed.row(v).transpose() - (r * body.shaped_vertices().row(v).transpose() + t)).norm(), 1e-12);
}

TEST(SmplModel, PoseBlendShapesAndBlendedSkinning) {
    std::mt19937_64 rng(3);
    const std::string path = write_test_model(test::scratch_dir("smpl_pose"), rng);
    const SmplBody body(smpl_spec(path));
    const auto npz = read_npz(path);
    const std::vector<double> posedirs = npz.at("posedirs").to<double>();
    // Bend the left elbow by 70 degrees about the vertical; everything else rests.
    const Matrix3d r = AngleAxisd(70 * M_PI / 180, Vector3d::UnitY()).toRotationMatrix();
    PosedFrame f = rest_frame(body);
    for (int s : {int(left_elbow), int(left_wrist)}) f.rotation[s] = r;
    f.joints[left_wrist] = f.joints[left_elbow] + r * (body.rest_joints()[left_wrist] - body.rest_joints()[left_elbow]);
    const SmplBody::Matrix posed = body.posed_vertices(f);
    // Pose feature: (R - I) of the elbow's local rotation (joint 18: entries 9*17 .. 9*17+8), zero elsewhere.
    Eigen::VectorXd feature = Eigen::VectorXd::Zero(kPoseDims);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) feature[9 * (left_elbow - 1) + 3 * a + b] = r(a, b) - (a == b ? 1 : 0);
    const auto corrected = [&](int v) {
        Vector3d x = body.shaped_vertices().row(v).transpose();
        for (int c = 0; c < 3; ++c)
            for (int d = 0; d < kPoseDims; ++d)
                x[c] += posedirs[static_cast<size_t>((3 * v + c) * kPoseDims + d)] * feature[d];
        return x;
    };
    const Vector3d elbow = body.rest_joints()[left_elbow];
    // A spine vertex moves only by its pose blend shape.
    const int spine_v = spine1 * kRing + 3;
    EXPECT_LT((posed.row(spine_v).transpose() - corrected(spine_v)).norm(), 1e-12);
    // A forearm vertex turns rigidly about the elbow (after its blend shape).
    const int fore_v = left_elbow * kRing + 2;
    EXPECT_LT((posed.row(fore_v).transpose() - (r * (corrected(fore_v) - elbow) + elbow)).norm(), 1e-12);
    // The shared vertex is the average of the two bones' transforms (linear blend skinning).
    const int shared = left_elbow * kRing;
    const Vector3d expect = 0.5 * corrected(shared) + 0.5 * (r * (corrected(shared) - elbow) + elbow);
    EXPECT_LT((posed.row(shared).transpose() - expect).norm(), 1e-12);
}

TEST(SmplModel, SensorsOnVerticesFollowTheSkin) {
    std::mt19937_64 rng(4);
    const std::string path = write_test_model(test::scratch_dir("smpl_sensor"), rng);
    const SmplBody body(smpl_spec(path));
    // Placements on segments land on a vertex of that segment on the asked-for side.
    const SurfacePoint p = body.surface_point(left_hip, 0.0, M_PI / 2);  // lateral (left) of the left hip ring
    const BodyAnchor a = body.anchor(left_hip, p);
    EXPECT_EQ(a.vertex, left_hip * kRing + 0);  // ring vertex 0 points to +X
    EXPECT_THROW(body.vertex_point(K * kRing), Error);
    // A turning body: the skinned vertex sensor reads the yaw rate, like a rigid one.
    JointSequence turn(61, kNumJoints, 20);
    for (int f = 0; f < 61; ++f) {
        const Matrix3d r = AngleAxisd(0.9 * f / 20.0, Vector3d::UnitY()).toRotationMatrix();
        for (int j = 0; j < kNumJoints; ++j) turn.at(f, j) = r * body.rest_joints()[j];
    }
    SensorPlacement place;
    place.position = "left_hip_skin";
    place.segment = left_hip;
    place.vertex = left_hip * kRing + 2;
    place.axis[0] = "front";  // the test rings are flat: their normals are vertical
    place.axis[2] = "out";
    const BodyImu imu = synthesize_body_imu(turn, smpl_spec(path), {place}, {});
    EXPECT_EQ(imu.mounts[0].anchor.vertex, place.vertex);
    for (const Vector3d& g : imu.signals[0].gyr) EXPECT_NEAR(g.norm(), 0.9, 2e-3);
    for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(imu.max_error_mm[j], 1e-6) << kJointNames[j];
}

TEST(SmplModel, RefusesFilesThatAreNotSmpl) {
    const std::string dir = test::scratch_dir("smpl_bad");
    std::mt19937_64 rng(5);
    const std::string path = write_test_model(dir, rng);
    auto npz = read_npz(path);
    npz.erase("posedirs");
    write_npz(dir + "/missing.npz", npz);
    EXPECT_THROW(SmplBody(smpl_spec(dir + "/missing.npz")), Error);
    npz = read_npz(path);
    std::vector<int64_t> tree = npz.at("kintree_table").to<int64_t>();
    tree[4] = 2;  // the left knee hangs from the right hip
    npz["kintree_table"] = NdArray::from(tree, {2, K});
    write_npz(dir + "/tree.npz", npz);
    EXPECT_THROW(SmplBody(smpl_spec(dir + "/tree.npz")), Error);
}
