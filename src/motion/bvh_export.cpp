#include "motion/bvh_export.hpp"

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "motion/humanml3d.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

constexpr double kCentimetres = 100.0;

// World rotation of the bone that leaves each joint, from HumanML3D's chain rotations: the pelvis keeps the
// body's facing, a joint with a child along a chain takes that bone's rotation (spine3 follows the neck),
// and an end joint (feet, head, wrists) takes its parent's.
std::array<Quat, 22> joint_world_rotations(const PoseQuats& q) {
    std::array<Quat, 22> bone;  // rotation of the bone parent(j) -> j
    bone[0] = q[0];
    for (int c = 0; c < 5; ++c) {
        Quat r = q[0];
        for (int k = 1; k < kKinematicChainLengths[static_cast<size_t>(c)]; ++k) {
            const int child = kKinematicChains[static_cast<size_t>(c)][static_cast<size_t>(k)];
            r = r * q[static_cast<size_t>(child)];
            bone[static_cast<size_t>(child)] = r;
        }
    }
    std::array<Quat, 22> world;
    world[0] = q[0];
    std::array<bool, 22> set{};
    set[0] = true;
    // The first chain child of each joint decides; chain 2 (spine) is visited before the arms so that spine3
    // follows its neck.
    for (int c : {2, 0, 1, 3, 4})
        for (int k = 1; k + 1 < kKinematicChainLengths[static_cast<size_t>(c)]; ++k) {
            const size_t j = static_cast<size_t>(kKinematicChains[static_cast<size_t>(c)][static_cast<size_t>(k)]);
            const size_t next =
                static_cast<size_t>(kKinematicChains[static_cast<size_t>(c)][static_cast<size_t>(k + 1)]);
            if (!set[j]) {
                world[j] = bone[next];
                set[j] = true;
            }
        }
    for (size_t j = 1; j < 22; ++j)
        if (!set[j]) world[j] = world[static_cast<size_t>(kParents[j])];
    return world;
}

}  // namespace

BvhMotion smpl22_to_bvh(const JointSequence& s) {
    if (s.num_joints != kNumJoints || s.num_frames < 1)
        throw Error("bvh export", "joints", "[frames >= 1, 22, 3]", std::to_string(s.num_joints) + " joints");
    BvhMotion m;
    m.frame_time = 1.0 / s.fps;
    m.num_frames = s.num_frames;
    const std::array<Vector3d, 22> rest = offsets_from_joints(s, 0);
    const std::vector<BvhChannel> channels = {BvhChannel::x_position, BvhChannel::y_position, BvhChannel::z_position,
                                              BvhChannel::z_rotation, BvhChannel::y_rotation, BvhChannel::x_rotation};
    // kParents lists parents before children, as BVH needs; End Sites close the leaves.
    for (int j = 0; j < kNumJoints; ++j) {
        BvhJoint joint;
        joint.name = kJointNames[static_cast<size_t>(j)];
        joint.parent = kParents[static_cast<size_t>(j)];
        joint.offset = rest[static_cast<size_t>(j)] * kCentimetres;
        joint.channels = channels;
        joint.first_channel = 6 * j;
        m.joints.push_back(joint);
    }
    m.num_channels = 6 * kNumJoints;
    for (int j : {left_foot, right_foot, head, left_wrist, right_wrist}) {
        BvhJoint end;
        end.name = std::string(kJointNames[static_cast<size_t>(j)]) + "/end";
        end.parent = j;
        end.offset = kRawOffsets[static_cast<size_t>(j)] * 10.0;  // a 10 cm tip so the last bone has a length
        end.end_site = true;
        m.joints.push_back(end);
    }
    const std::vector<PoseQuats> ik = inverse_kinematics(s, false);
    m.values.reserve(static_cast<size_t>(m.num_frames) * static_cast<size_t>(m.num_channels));
    for (int f = 0; f < s.num_frames; ++f) {
        const std::array<Quat, 22> world = joint_world_rotations(ik[static_cast<size_t>(f)]);
        for (int j = 0; j < kNumJoints; ++j) {
            const int p = kParents[static_cast<size_t>(j)];
            const Quat parent = p < 0 ? Quat::Identity() : world[static_cast<size_t>(p)];
            const Vector3d from_parent = p < 0 ? s.at(f, j) : Vector3d(s.at(f, j) - s.at(f, p));
            const Vector3d t = parent.conjugate() * from_parent * kCentimetres;
            const Eigen::Matrix3d local = (parent.conjugate() * world[static_cast<size_t>(j)]).toRotationMatrix();
            const Vector3d zyx = local.eulerAngles(2, 1, 0) * (180.0 / M_PI);  // local = Rz Ry Rx
            for (double v : {t.x(), t.y(), t.z(), zyx[0], zyx[1], zyx[2]}) m.values.push_back(v);
        }
    }
    return m;
}

void write_bvh(const std::string& path, const BvhMotion& motion) { write_file_atomic(path, format_bvh(motion)); }

}  // namespace t2imu
