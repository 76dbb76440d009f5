// Quaternion helpers with the conventions of HumanML3D's common/quaternion.py, so that its numbers are
// reproduced: quaternions are (w, x, y, z) stored in Eigen::Quaterniond, products are Hamilton products
// (q * r applies r first), rotations are active (qrot(q, v) = q v q*). The continuous 6D representation is the
// first two COLUMNS of the rotation matrix, concatenated (Zhou et al. 2019).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace t2imu {

using Quat = Eigen::Quaterniond;
using Cont6d = Eigen::Matrix<double, 6, 1>;

inline Quat qmul(const Quat& q, const Quat& r) { return q * r; }
inline Quat qinv(const Quat& q) { return q.conjugate(); }  // the inverse of a unit quaternion
// Rotates v by q without normalising q (v + 2 (w u x v + u x (u x v)), u = vec(q)), as the reference does.
Eigen::Vector3d qrot(const Quat& q, const Eigen::Vector3d& v);
// The shortest-arc rotation taking direction v0 to direction v1 (normalised; undefined for opposite vectors).
Quat qbetween(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1);
// Rotation matrix of q scaled by 2/|q|^2, so a non-unit q still gives a rotation.
Eigen::Matrix3d quaternion_to_matrix(const Quat& q);
Cont6d quaternion_to_cont6d(const Quat& q);
// Gram-Schmidt of the two columns back to a rotation matrix.
Eigen::Matrix3d cont6d_to_matrix(const Cont6d& c);
// Spherical linear interpolation along the shorter arc; t in [0, 1].
Quat slerp(const Quat& q0, const Quat& q1, double t);

// Flips signs over time so that consecutive quaternions of each joint have a non-negative dot product
// (qfix): a rotation and its negative are the same rotation, but interpolation and finite differences need
// one continuous branch. frames[f][j].
template <size_t N>
void qfix(std::vector<std::array<Quat, N>>& frames) {
    for (size_t f = 1; f < frames.size(); ++f)
        for (size_t j = 0; j < N; ++j)
            if (frames[f][j].coeffs().dot(frames[f - 1][j].coeffs()) < 0) frames[f][j].coeffs() *= -1.0;
}
// The same for one track of rotations.
inline void qfix(std::vector<Quat>& track) {
    for (size_t f = 1; f < track.size(); ++f)
        if (track[f].coeffs().dot(track[f - 1].coeffs()) < 0) track[f].coeffs() *= -1.0;
}

}  // namespace t2imu
