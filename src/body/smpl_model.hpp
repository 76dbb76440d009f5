// A user-supplied SMPL body (Loper et al. 2015) in NumPy .npz form: shape blend shapes, pose blend shapes and
// linear blend skinning, with sensors on skin vertices.
//
// The .npz holds the arrays of the official model file: v_template [V,3], shapedirs [V,3,B], posedirs
// [V,3,9(K-1)], J_regressor [K,V] (dense), weights [V,K], kintree_table [2,K] (first row: parents), f [T,3];
// K = 24, the first 22 joints are SMPL-22. Converting the official SMPL_*.pkl (Python 3, chumpy installed or
// the "SMPL for Python" 1.1 files, which need none):
//     import pickle, numpy as np
//     m = pickle.load(open("SMPL_NEUTRAL.pkl", "rb"), encoding="latin1")
//     a = lambda k: np.asarray(m[k].toarray() if hasattr(m[k], "toarray") else m[k])
//     np.savez("smpl_neutral.npz", **{k: a(k).astype(np.int64 if k in ("kintree_table", "f") else np.float64)
//              for k in ("v_template", "shapedirs", "posedirs", "J_regressor", "weights", "kintree_table", "f")})
// then `t2imu imu synth --body smpl:smpl_neutral.npz,betas=0.5;-1.2 ...`.
//
// Conventions: SMPL's canonical frame is Y up, facing +Z, like ours; the rest pose is its T-pose. The model is
// shifted so that its lowest vertex is at y = 0. Posing uses the segment orientations of segments.hpp as SMPL
// global joint rotations (world from T-pose); the hands (joints 22, 23) follow the wrists.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "body/body_model.hpp"

namespace t2imu {

class SmplBody : public BodyModel {
public:
    using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    static constexpr int kJoints = 24;

    SmplBody(const BodySpec& spec);

    const BodySpec& spec() const override { return spec_; }
    const Joints22& rest_joints() const override { return rest22_; }
    SurfacePoint surface_point(int segment, double along, double around) const override;
    SurfacePoint vertex_point(int vertex) const override;
    BodyAnchor anchor(int segment, const SurfacePoint& p) const override;
    void pose_anchor(const BodyAnchor& a, const PosedFrame& frame, Eigen::Vector3d* position,
                     Eigen::Matrix3d* rotation) const override;

    int num_vertices() const { return static_cast<int>(shaped_.rows()); }
    const Matrix& shaped_vertices() const { return shaped_; }  // [V,3] rest, after shape blend shapes
    // All posed vertices [V,3] (skinning with pose blend shapes), for checks and exports.
    Matrix posed_vertices(const PosedFrame& frame) const;

private:
    void global_transforms(const PosedFrame& frame, std::vector<Eigen::Matrix3d>* r,
                           std::vector<Eigen::Vector3d>* x) const;
    Eigen::VectorXd pose_feature(const std::vector<Eigen::Matrix3d>& r) const;  // 9 (K-1) values
    Eigen::Vector3d skin(int v, const std::vector<Eigen::Matrix3d>& r, const std::vector<Eigen::Vector3d>& x,
                         const Eigen::VectorXd& feature) const;

    BodySpec spec_;
    Matrix shaped_;    // [V,3]
    Matrix posedirs_;  // [V*3, 9(K-1)]
    Matrix weights_;   // [V,K]
    Matrix normals_;   // [V,3] rest vertex normals
    std::vector<int> parents_;
    std::vector<Eigen::Vector3d> joints_;  // K rest joints
    std::vector<int> dominant_;            // per vertex: the SMPL-22 segment with the largest weight
    Joints22 rest22_;
    RestAxes axes_;
};

}  // namespace t2imu
