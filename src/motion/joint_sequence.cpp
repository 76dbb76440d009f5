#include "motion/joint_sequence.hpp"

#include <algorithm>

#include <cmath>

#include "core/error.hpp"

namespace t2imu {

JointSequence::JointSequence(int frames, int joints, double fps_)
    : num_frames(frames),
      num_joints(joints),
      fps(fps_),
      positions(static_cast<size_t>(frames) * static_cast<size_t>(joints), Eigen::Vector3d::Zero()) {}

void check_motion_fps(double fps, const std::string& option) {
    if (!(fps > 0 && fps <= 1000))
        throw Error(option, "frame rate", "above 0 and at most 1000 fps", std::to_string(fps));
}

double lowest_joint_height_at(const JointSequence& s, int frame) {
    double low = s.at(frame, 0).y();
    for (int j = 1; j < s.num_joints; ++j) low = std::min(low, s.at(frame, j).y());
    return low;
}

double lowest_joint_height(const JointSequence& s) {
    double low = lowest_joint_height_at(s, 0);
    for (int f = 1; f < s.num_frames; ++f) low = std::min(low, lowest_joint_height_at(s, f));
    return low;
}

JointSequence slice_frames(const JointSequence& s, int begin, int end) {
    JointSequence out(end - begin, s.num_joints, s.fps);
    std::copy(s.positions.begin() + static_cast<std::ptrdiff_t>(begin) * s.num_joints,
              s.positions.begin() + static_cast<std::ptrdiff_t>(end) * s.num_joints, out.positions.begin());
    return out;
}

JointSequence concatenate_frames(const JointSequence& a, const JointSequence& b) {
    if (a.num_joints != b.num_joints || a.fps != b.fps)
        throw Error("concatenate_frames", "b",
                    std::to_string(a.num_joints) + " joints at " + std::to_string(a.fps) + " fps",
                    std::to_string(b.num_joints) + " joints at " + std::to_string(b.fps) + " fps");
    JointSequence out(a.num_frames + b.num_frames, a.num_joints, a.fps);
    std::copy(a.positions.begin(), a.positions.end(), out.positions.begin());
    std::copy(b.positions.begin(), b.positions.end(),
              out.positions.begin() + static_cast<std::ptrdiff_t>(a.positions.size()));
    return out;
}

static void require_finite(const std::vector<double>& v, const std::string& source) {
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw Error(source, "values", "finite numbers", "NaN or inf at flat index " + std::to_string(i));
}

JointSequence joint_sequence_from_array(const NdArray& a, const std::string& source, int joints, int min_frames,
                                        double fps) {
    if (a.shape.size() != 3 || a.shape[2] != 3) throw Error(source, "shape", "[frames, joints, 3]", a.shape_str());
    if (joints > 0 && a.shape[1] != joints)
        throw Error(source, "shape", std::to_string(joints) + " joints", a.shape_str());
    if (a.shape[0] < min_frames)
        throw Error(source, "shape", "at least " + std::to_string(min_frames) + " frames", a.shape_str());
    const std::vector<double> v = a.to<double>();
    require_finite(v, source);
    JointSequence s(static_cast<int>(a.shape[0]), static_cast<int>(a.shape[1]), fps);
    for (size_t i = 0; i < s.positions.size(); ++i) s.positions[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return s;
}

NdArray joint_sequence_to_array(const JointSequence& s) {
    std::vector<float> v(s.positions.size() * 3);
    for (size_t i = 0; i < s.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + static_cast<size_t>(k)] = static_cast<float>(s.positions[i][k]);
    return NdArray::from(v, {s.num_frames, s.num_joints, 3});
}

FeatureMatrix feature_matrix_from_array(const NdArray& a, const std::string& source, int channels) {
    if (a.shape.size() != 2 || (channels > 0 && a.shape[1] != channels))
        throw Error(source, "shape", "[frames, " + std::to_string(channels) + "]", a.shape_str());
    const std::vector<double> v = a.to<double>();
    require_finite(v, source);
    FeatureMatrix m(a.shape[0], a.shape[1]);
    std::copy(v.begin(), v.end(), m.data());
    return m;
}

NdArray feature_matrix_to_array(const FeatureMatrix& m) {
    std::vector<float> v(static_cast<size_t>(m.size()));
    for (Eigen::Index i = 0; i < m.size(); ++i) v[static_cast<size_t>(i)] = static_cast<float>(m.data()[i]);
    return NdArray::from(v, {m.rows(), m.cols()});
}

}  // namespace t2imu
