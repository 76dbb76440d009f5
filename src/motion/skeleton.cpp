#include "motion/skeleton.hpp"

namespace t2imu::smpl22 {

const std::array<const char*, kNumJoints> kJointNames = {
    "pelvis",     "left_hip",    "right_hip",    "spine1",     "left_knee",     "right_knee",
    "spine2",     "left_ankle",  "right_ankle",  "spine3",     "left_foot",     "right_foot",
    "neck",       "left_collar", "right_collar", "head",       "left_shoulder", "right_shoulder",
    "left_elbow", "right_elbow", "left_wrist",   "right_wrist"};

const std::array<int, kNumJoints> kParents = {-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19};

const std::array<Eigen::Vector3d, kNumJoints> kRawOffsets = {
    {{0, 0, 0},  {1, 0, 0},  {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}, {0, -1, 0}, {0, 1, 0},  {0, -1, 0},
     {0, -1, 0}, {0, 1, 0},  {0, 0, 1},  {0, 0, 1},  {0, 1, 0},  {1, 0, 0},  {-1, 0, 0}, {0, 0, 1},
     {0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}}};

const std::array<std::array<int, 6>, 5> kKinematicChains = {{{0, 2, 5, 8, 11, -1},
                                                             {0, 1, 4, 7, 10, -1},
                                                             {0, 3, 6, 9, 12, 15},
                                                             {9, 14, 17, 19, 21, -1},
                                                             {9, 13, 16, 18, 20, -1}}};
const std::array<int, 5> kKinematicChainLengths = {5, 5, 6, 5, 5};

// float32 values of HumanML3D's tgt_offsets, written out in full so that double arithmetic starts from
// exactly the numbers the reference implementation uses.
const std::array<Eigen::Vector3d, kNumJoints> kTargetOffsets = {{{0.0, 0.0, 0.0},
                                                                 {0.10307393223047256, 0.0, 0.0},
                                                                 {-0.10988342016935349, 0.0, 0.0},
                                                                 {0.0, 0.13156823813915253, 0.0},
                                                                 {0.0, -0.3936232626438141, 0.0},
                                                                 {0.0, -0.3901881277561188, 0.0},
                                                                 {0.0, 0.14319021999835968, 0.0},
                                                                 {0.0, -0.4324330985546112, 0.0},
                                                                 {0.0, -0.42564353346824646, 0.0},
                                                                 {0.0, 0.05736473575234413, 0.0},
                                                                 {0.0, 0.0, 0.14338184893131256},
                                                                 {0.0, 0.0, 0.14941902458667755},
                                                                 {0.0, 0.21936005353927612, 0.0},
                                                                 {0.13748674094676971, 0.0, 0.0},
                                                                 {-0.14338286221027374, 0.0, 0.0},
                                                                 {0.0, 0.0, 0.1030392199754715},
                                                                 {0.0, -0.13161404430866241, 0.0},
                                                                 {0.0, -0.12298443913459778, 0.0},
                                                                 {0.0, -0.25683990120887756, 0.0},
                                                                 {0.0, -0.26309171319007874, 0.0},
                                                                 {0.0, -0.26601195335388184, 0.0},
                                                                 {0.0, -0.2698764503002167, 0.0}}};

const std::array<int, kNumJoints> kMirror = {0,  2,  1,  3,  5,  4,  6,  8,  7,  9,  11,
                                             10, 12, 14, 13, 15, 17, 16, 19, 18, 21, 20};

}  // namespace t2imu::smpl22
