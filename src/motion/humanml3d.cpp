#include "motion/humanml3d.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

const Vector3d kUp(0, 1, 0);
const Vector3d kFacing(0, 0, 1);

// The official IK and FK run in float32: its quaternion helpers cast their inputs to float32 torch tensors and
// compute there. Some of these steps are ill-conditioned (the shortest arc between nearly opposite directions
// cancels in w), so rounding a double result is not enough: the three helpers below repeat the reference's
// float32 operations in the same order. Without them, long chains (spine to head) land up to 2e-5 away from the
// released features.
using Vec3f = Eigen::Vector3f;
using Quatf = Eigen::Vector4f;  // (w, x, y, z) in float32

Vec3f cross_f32(const Vec3f& a, const Vec3f& b) {
    return Vec3f(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}
float sum3(float a, float b, float c) { return (a + b) + c; }

Quatf qbetween_f32(const Vec3f& v0, const Vec3f& v1) {
    const Vec3f v = cross_f32(v0, v1);
    const float n0 = sum3(v0.x() * v0.x(), v0.y() * v0.y(), v0.z() * v0.z());
    const float n1 = sum3(v1.x() * v1.x(), v1.y() * v1.y(), v1.z() * v1.z());
    const float w = std::sqrt(n0 * n1) + sum3(v0.x() * v1.x(), v0.y() * v1.y(), v0.z() * v1.z());
    const Quatf q(w, v.x(), v.y(), v.z());
    const float norm = std::sqrt(((q[0] * q[0] + q[1] * q[1]) + q[2] * q[2]) + q[3] * q[3]);
    return q / norm;
}

Quatf qmul_f32(const Quatf& q, const Quatf& r) {
    // terms[i][j] = r[i] * q[j], combined in the reference's order.
    auto t = [&](int i, int j) { return r[i] * q[j]; };
    return Quatf(((t(0, 0) - t(1, 1)) - t(2, 2)) - t(3, 3), ((t(0, 1) + t(1, 0)) - t(2, 3)) + t(3, 2),
                 ((t(0, 2) + t(1, 3)) + t(2, 0)) - t(3, 1), ((t(0, 3) - t(1, 2)) + t(2, 1)) + t(3, 0));
}

Quatf qinv_f32(const Quatf& q) { return Quatf(q[0], -q[1], -q[2], -q[3]); }

Vec3f qrot_f32(const Quatf& q, const Vec3f& v) {
    const Vec3f u(q[1], q[2], q[3]);
    const Vec3f uv = cross_f32(u, v);
    const Vec3f uuv = cross_f32(u, uv);
    return v + 2.0f * (q[0] * uv + uuv);
}

Quat to_quat(const Quatf& q) { return Quat(q[0], q[1], q[2], q[3]); }
Quatf to_quatf(const Quat& q) {
    return Quatf(static_cast<float>(q.w()), static_cast<float>(q.x()), static_cast<float>(q.y()),
                 static_cast<float>(q.z()));
}
Vec3f to_f32(const Vector3d& v) { return v.cast<float>(); }
Vector3d f32(const Vector3d& v) { return v.cast<float>().cast<double>(); }

void require_motion(const JointSequence& joints, int min_frames, const char* what) {
    if (joints.num_joints != kNumJoints)
        throw Error(what, "joints", "22 SMPL joints", std::to_string(joints.num_joints));
    if (joints.num_frames < min_frames)
        throw Error(what, "frames", "at least " + std::to_string(min_frames), std::to_string(joints.num_frames));
    for (const Vector3d& p : joints.positions)
        if (!p.allFinite()) throw Error(what, "positions", "finite joint positions", "NaN or inf");
}

// Forward direction of one frame from the hips and shoulders, given the across-body vector's joints.
Vector3d across_body(const JointSequence& s, int f, int a_plus, int a_minus, int b_plus, int b_minus) {
    return (s.at(f, a_plus) - s.at(f, a_minus)) + (s.at(f, b_plus) - s.at(f, b_minus));
}

std::vector<Quat> root_facing_rotations(const JointSequence& joints, bool smooth_forward) {
    const int n = joints.num_frames;
    TimeSeries forward(n, 3);
    for (int f = 0; f < n; ++f) {
        // inverse_kinematics_np unpacks face_joint_indx [2,1,17,16] as l_hip, r_hip, sdr_r, sdr_l.
        const Vector3d across = across_body(joints, f, left_hip, right_hip, right_shoulder, left_shoulder).normalized();
        forward.row(f) = kUp.cross(across).transpose();
    }
    if (smooth_forward) forward = gaussian_filter1d_nearest(forward, 20.0).cast<float>().cast<double>();
    std::vector<Quat> root(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f)
        root[static_cast<size_t>(f)] =
            to_quat(qbetween_f32(to_f32(forward.row(f).transpose().normalized()), kFacing.cast<float>()));
    // Official quirk (common/skeleton.py at the HumanML3D release): the first frame's root rotation is set to
    // the identity, whatever the body's facing. It shows in the features (frame 0 of ric and the first root
    // rotation velocity), so it is kept.
    root[0] = Quat::Identity();
    return root;
}

template <class Fn>
void for_each_chain_bone(Fn fn) {
    for (int c = 0; c < 5; ++c)
        for (int k = 1; k < kKinematicChainLengths[static_cast<size_t>(c)]; ++k)
            fn(kKinematicChains[static_cast<size_t>(c)][static_cast<size_t>(k - 1)],
               kKinematicChains[static_cast<size_t>(c)][static_cast<size_t>(k)], k == 1);
}

// foot_detect: squared displacement between consecutive frames below the threshold.
void foot_contacts(const JointSequence& p, double threshold, FeatureMatrix& features) {
    const std::array<int, 4> feet = {kFootLeft[0], kFootLeft[1], kFootRight[0], kFootRight[1]};
    for (int f = 0; f + 1 < p.num_frames; ++f)
        for (int k = 0; k < 4; ++k) {
            const double d2 =
                (p.at(f + 1, feet[static_cast<size_t>(k)]) - p.at(f, feet[static_cast<size_t>(k)])).squaredNorm();
            features(f, 259 + k) = d2 < threshold ? 1.0 : 0.0;
        }
}

}  // namespace

std::array<Vector3d, 22> offsets_from_joints(const JointSequence& joints, int frame) {
    std::array<Vector3d, 22> off;
    off[0] = kRawOffsets[0];
    for (int j = 1; j < kNumJoints; ++j)
        off[static_cast<size_t>(j)] =
            f32((joints.at(frame, j) - joints.at(frame, kParents[static_cast<size_t>(j)])).norm() *
                kRawOffsets[static_cast<size_t>(j)]);
    return off;
}

std::vector<PoseQuats> inverse_kinematics(const JointSequence& joints, bool smooth_forward) {
    require_motion(joints, 1, "inverse_kinematics");
    const std::vector<Quat> root = root_facing_rotations(joints, smooth_forward);
    std::vector<PoseQuats> quats(static_cast<size_t>(joints.num_frames));
    for (int f = 0; f < joints.num_frames; ++f) {
        PoseQuats& q = quats[static_cast<size_t>(f)];
        q[0] = root[static_cast<size_t>(f)];
        // Every chain starts again from the root rotation, the arms too (they hang off spine3 but the official
        // IK and FK both restart from the root): kept, since the features depend on it.
        Quatf chain_rot;
        for_each_chain_bone([&](int parent, int child, bool chain_start) {
            if (chain_start) chain_rot = to_quatf(q[0]);
            const Vector3d dir = (joints.at(f, child) - joints.at(f, parent)).normalized();
            const Quatf world = qbetween_f32(kRawOffsets[static_cast<size_t>(child)].cast<float>(), to_f32(dir));
            const Quatf local = qmul_f32(qinv_f32(chain_rot), world);
            q[static_cast<size_t>(child)] = to_quat(local);
            chain_rot = qmul_f32(chain_rot, local);
        });
    }
    return quats;
}

JointSequence forward_kinematics(const std::vector<PoseQuats>& quats, const std::vector<Vector3d>& root_pos,
                                 const std::array<Vector3d, 22>& offsets) {
    JointSequence out(static_cast<int>(quats.size()), kNumJoints, kFps);
    for (int f = 0; f < out.num_frames; ++f) {
        const PoseQuats& q = quats[static_cast<size_t>(f)];
        out.at(f, 0) = root_pos[static_cast<size_t>(f)];
        Quatf chain_rot;
        for_each_chain_bone([&](int parent, int child, bool chain_start) {
            if (chain_start) chain_rot = to_quatf(q[0]);
            chain_rot = qmul_f32(chain_rot, to_quatf(q[static_cast<size_t>(child)]));
            const Vec3f bone = qrot_f32(chain_rot, offsets[static_cast<size_t>(child)].cast<float>());
            out.at(f, child) = bone.cast<double>() + out.at(f, parent);
        });
    }
    return out;
}

JointSequence uniform_skeleton(const JointSequence& joints, const std::array<Vector3d, 22>& target_offsets) {
    const std::array<Vector3d, 22> src = offsets_from_joints(joints, 0);
    // Scale by the ratio of lower-leg lengths (knee->ankle and ankle->foot of the right leg: l_idx1, l_idx2).
    auto leg = [](const std::array<Vector3d, 22>& o) {
        return o[right_knee].cwiseAbs().maxCoeff() + o[right_ankle].cwiseAbs().maxCoeff();
    };
    const double scale = static_cast<float>(leg(target_offsets) / leg(src));  // float32, as the reference
    std::vector<Vector3d> root(static_cast<size_t>(joints.num_frames));
    for (int f = 0; f < joints.num_frames; ++f) root[static_cast<size_t>(f)] = joints.at(f, 0) * scale;
    JointSequence out = forward_kinematics(inverse_kinematics(joints, false), root, target_offsets);
    out.fps = joints.fps;
    return out;
}

namespace {

// Where process_file puts a retargeted motion: its lowest joint on the floor, its root's frame-0 XZ at the
// origin, its frame-0 facing turned to +Z.
struct Placement {
    double floor = 0;
    Vector3d root_xz;
    Vector3d forward;  // frame 0's facing before the turn
    Quatf rotation;
};

Placement placement_of(const JointSequence& p) {
    Placement out;
    out.floor = p.positions[0].y();
    for (const Vector3d& v : p.positions) out.floor = std::min(out.floor, v.y());
    out.root_xz = Vector3d(p.at(0, 0).x(), 0, p.at(0, 0).z());
    // process_file unpacks face_joint_indx [2,1,17,16] as r_hip, l_hip, sdr_r, sdr_l.
    const Vector3d across = across_body(p, 0, right_hip, left_hip, right_shoulder, left_shoulder).normalized();
    out.forward = kUp.cross(across).normalized();
    out.rotation = qbetween_f32(to_f32(out.forward), kFacing.cast<float>());
    return out;
}

// The official code holds the canonicalised positions in float32 (its qrot returns float32), and every later
// quantity is computed from them; rounding here is what keeps short bones (the head: 0.10 m) within 1e-5 of the
// released features.
JointSequence placed(JointSequence p, const Placement& at) {
    for (Vector3d& v : p.positions) {
        v.y() -= at.floor;
        v = qrot_f32(at.rotation, to_f32(v - at.root_xz)).cast<double>();
    }
    return p;
}

}  // namespace

JointSequence place_like_process_file(const JointSequence& joints, const JointSequence& reference) {
    require_motion(joints, 1, "place_like_process_file");
    return placed(uniform_skeleton(joints, kTargetOffsets), placement_of(uniform_skeleton(reference, kTargetOffsets)));
}

ProcessFileResult process_file(const JointSequence& joints, double feet_threshold) {
    require_motion(joints, 2, "process_file");
    ProcessFileResult r;
    r.after_uniform_skeleton = uniform_skeleton(joints, kTargetOffsets);
    const Placement placement = placement_of(r.after_uniform_skeleton);
    r.forward_init = placement.forward;
    r.root_quat_init = to_quat(placement.rotation);
    JointSequence p = r.global_positions = placed(r.after_uniform_skeleton, placement);
    const int n = p.num_frames;

    FeatureMatrix& d = r.features;
    d = FeatureMatrix::Zero(n - 1, kFeatureDim);
    foot_contacts(p, feet_threshold, d);

    r.ik_quats_smooth = inverse_kinematics(p, true);
    std::vector<Quat> r_rot(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f) r_rot[static_cast<size_t>(f)] = r.ik_quats_smooth[static_cast<size_t>(f)][0];

    // get_rifke: subtract the root's XZ, then turn every frame to face +Z.
    r.local_positions = p;
    for (int f = 0; f < n; ++f) {
        const Vector3d root_xz(p.at(f, 0).x(), 0, p.at(f, 0).z());
        for (int j = 0; j < kNumJoints; ++j)
            r.local_positions.at(f, j) = qrot(r_rot[static_cast<size_t>(f)], p.at(f, j) - root_xz);
    }

    r.l_velocity.resize(n - 1, 2);
    for (int f = 0; f + 1 < n; ++f) {
        const size_t t = static_cast<size_t>(f);
        const Vector3d vel = qrot(r_rot[t + 1], p.at(f + 1, 0) - p.at(f, 0));
        const Quat r_vel = qmul(r_rot[t + 1], qinv(r_rot[t]));
        r.l_velocity(f, 0) = vel.x();
        r.l_velocity(f, 1) = vel.z();
        d(f, 0) = std::asin(r_vel.y());
        d(f, 1) = vel.x();
        d(f, 2) = vel.z();
        d(f, 3) = r.local_positions.at(f, 0).y();
        for (int j = 1; j < kNumJoints; ++j) {
            d.block<1, 3>(f, 4 + 3 * (j - 1)) = r.local_positions.at(f, j).transpose();
            d.block<1, 6>(f, 67 + 6 * (j - 1)) =
                quaternion_to_cont6d(r.ik_quats_smooth[t][static_cast<size_t>(j)]).transpose();
        }
        for (int j = 0; j < kNumJoints; ++j)
            d.block<1, 3>(f, 193 + 3 * j) = qrot(r_rot[t], p.at(f + 1, j) - p.at(f, j)).transpose();
    }
    return r;
}

FeatureMatrix joints_to_features(const JointSequence& joints) { return process_file(joints).features; }

static void require_features(const FeatureMatrix& d, const char* what) {
    if (d.cols() != kFeatureDim) throw Error(what, "features", "263 channels", std::to_string(d.cols()));
    if (d.rows() < 1) throw Error(what, "features", "at least one frame", "0");
}

RootTrajectory recover_root_rot_pos(const FeatureMatrix& d) {
    require_features(d, "recover_root_rot_pos");
    const size_t n = static_cast<size_t>(d.rows());
    RootTrajectory root{std::vector<Quat>(n), std::vector<Vector3d>(n)};
    double angle = 0;  // half-angle, as stored in channel 0
    Vector3d pos = Vector3d::Zero();
    for (Eigen::Index f = 0; f < d.rows(); ++f) {
        if (f > 0) angle += d(f - 1, 0);
        const Quat q(std::cos(angle), 0, std::sin(angle), 0);
        if (f > 0) pos += qrot(qinv(q), Vector3d(d(f - 1, 1), 0, d(f - 1, 2)));
        root.rotation[static_cast<size_t>(f)] = q;
        root.position[static_cast<size_t>(f)] = Vector3d(pos.x(), d(f, 3), pos.z());
    }
    return root;
}

JointSequence recover_from_ric(const FeatureMatrix& d) {
    const RootTrajectory root = recover_root_rot_pos(d);
    const std::vector<Quat>& rq = root.rotation;
    const std::vector<Vector3d>& rp = root.position;
    JointSequence out(static_cast<int>(d.rows()), kNumJoints, kFps);
    for (int f = 0; f < out.num_frames; ++f) {
        const size_t t = static_cast<size_t>(f);
        out.at(f, 0) = rp[t];
        for (int j = 1; j < kNumJoints; ++j) {
            Vector3d v = qrot(qinv(rq[t]), d.block<1, 3>(f, 4 + 3 * (j - 1)).transpose());
            out.at(f, j) = v + Vector3d(rp[t].x(), 0, rp[t].z());
        }
    }
    return out;
}

JointSequence recover_from_rot(const FeatureMatrix& d, const std::array<Vector3d, 22>& offsets) {
    const RootTrajectory root = recover_root_rot_pos(d);
    const std::vector<Quat>& rq = root.rotation;
    const std::vector<Vector3d>& rp = root.position;
    JointSequence out(static_cast<int>(d.rows()), kNumJoints, kFps);
    for (int f = 0; f < out.num_frames; ++f) {
        const size_t t = static_cast<size_t>(f);
        std::array<Eigen::Matrix3d, 22> local;
        local[0] = quaternion_to_matrix(rq[t]);
        for (int j = 1; j < kNumJoints; ++j)
            local[static_cast<size_t>(j)] = cont6d_to_matrix(d.block<1, 6>(f, 67 + 6 * (j - 1)).transpose());
        out.at(f, 0) = rp[t];
        Eigen::Matrix3d chain_rot;
        for_each_chain_bone([&](int parent, int child, bool chain_start) {
            if (chain_start) chain_rot = local[0];
            chain_rot = chain_rot * local[static_cast<size_t>(child)];
            out.at(f, child) = chain_rot * offsets[static_cast<size_t>(child)] + out.at(f, parent);
        });
    }
    return out;
}

}  // namespace t2imu
