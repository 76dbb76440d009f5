#include "body/smpl_model.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "core/npz.hpp"

namespace t2imu {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

SmplBody::Matrix member(const std::map<std::string, NdArray>& npz, const std::string& name, const std::string& path,
                        int64_t rows, int64_t cols, std::vector<int64_t> expect_tail) {
    const NdArray& a = npz_member(npz, name, path);
    if (a.shape.empty() || (rows >= 0 && a.shape[0] != rows))
        throw Error(path, name, "first dimension " + std::to_string(rows), a.shape_str());
    std::vector<int64_t> tail(a.shape.begin() + 1, a.shape.end());
    if (!expect_tail.empty() && tail != expect_tail) throw Error(path, name, "a different shape", a.shape_str());
    const std::vector<double> v = a.to<double>();
    for (double x : v)
        if (!std::isfinite(x)) throw Error(path, name, "finite values", "NaN or inf");
    SmplBody::Matrix m(a.shape[0], cols);
    if (static_cast<int64_t>(v.size()) != a.shape[0] * cols)
        throw Error(path, name, "a consistent shape", a.shape_str());
    std::copy(v.begin(), v.end(), m.data());
    return m;
}

}  // namespace

SmplBody::SmplBody(const BodySpec& spec) : spec_(spec) {
    const std::string& path = spec.smpl_path;
    const auto npz = read_npz(path);
    const NdArray& vt = npz_member(npz, "v_template", path);
    if (vt.shape.size() != 2 || vt.shape[1] != 3 || vt.shape[0] < 1)
        throw Error(path, "v_template", "[V,3]", vt.shape_str());
    const int64_t V = vt.shape[0];
    const NdArray& sd = npz_member(npz, "shapedirs", path);
    if (sd.shape.size() != 3 || sd.shape[0] != V || sd.shape[1] != 3)
        throw Error(path, "shapedirs", "[V,3,B]", sd.shape_str());
    const int64_t B = sd.shape[2];
    if (static_cast<int64_t>(spec.betas.size()) > B)
        throw Error(path, "betas", "at most " + std::to_string(B) + " shape coefficients",
                    std::to_string(spec.betas.size()));
    const Matrix tmpl = member(npz, "v_template", path, V, 3, {3});
    const Matrix shapedirs = member(npz, "shapedirs", path, V, 3 * B, {3, B});
    Matrix posedirs = member(npz, "posedirs", path, V, 3 * 9 * (kJoints - 1), {3, 9 * (kJoints - 1)});
    posedirs_ = Eigen::Map<Matrix>(posedirs.data(), V * 3, 9 * (kJoints - 1));  // row 3 v + c
    const Matrix regressor = member(npz, "J_regressor", path, kJoints, V, {V});
    weights_ = member(npz, "weights", path, V, kJoints, {kJoints});
    const Matrix kintree = member(npz, "kintree_table", path, 2, kJoints, {kJoints});
    const Matrix faces = member(npz, "f", path, -1, 3, {3});

    Eigen::VectorXd betas = Eigen::VectorXd::Zero(B);
    for (size_t i = 0; i < spec.betas.size(); ++i) betas[static_cast<Eigen::Index>(i)] = spec.betas[i];
    shaped_ = tmpl;
    for (int64_t v = 0; v < V; ++v)
        for (int c = 0; c < 3; ++c) shaped_(v, c) += shapedirs.row(v).segment(c * B, B).dot(betas);
    const double floor = shaped_.col(1).minCoeff();
    shaped_.col(1).array() -= floor;  // soles at y = 0

    parents_.resize(kJoints);
    for (int k = 0; k < kJoints; ++k) {
        const double p = kintree(0, k);
        parents_[static_cast<size_t>(k)] = (p >= 0 && p < kJoints) ? static_cast<int>(p) : -1;
    }
    for (int k = 0; k < smpl22::kNumJoints; ++k)
        if (parents_[static_cast<size_t>(k)] != smpl22::kParents[static_cast<size_t>(k)])
            throw Error(path, "kintree_table",
                        "SMPL's joint tree (parent of joint " + std::to_string(k) + " = " +
                            std::to_string(smpl22::kParents[static_cast<size_t>(k)]) + ")",
                        std::to_string(parents_[static_cast<size_t>(k)]));
    joints_.resize(kJoints);
    for (int k = 0; k < kJoints; ++k) joints_[static_cast<size_t>(k)] = (regressor.row(k) * shaped_).transpose();
    for (int k = 0; k < smpl22::kNumJoints; ++k) rest22_[static_cast<size_t>(k)] = joints_[static_cast<size_t>(k)];
    axes_ = rest_axes(rest22_);

    normals_ = Matrix::Zero(V, 3);
    for (Eigen::Index t = 0; t < faces.rows(); ++t) {
        int idx[3];
        for (int c = 0; c < 3; ++c) {
            const double fv = faces(t, c);
            if (!(fv >= 0 && fv < static_cast<double>(V)))
                throw Error(path, "f", "vertex indices below " + std::to_string(V), std::to_string(fv));
            idx[c] = static_cast<int>(fv);
        }
        const Vector3d a = shaped_.row(idx[0]), b = shaped_.row(idx[1]), c = shaped_.row(idx[2]);
        const Vector3d n = (b - a).cross(c - a);  // area-weighted
        for (int i : idx) normals_.row(i) += n.transpose();
    }
    dominant_.resize(static_cast<size_t>(V));
    for (int64_t v = 0; v < V; ++v) {
        if (normals_.row(v).norm() > 0) normals_.row(v).normalize();
        Eigen::Index k = 0;
        weights_.row(v).maxCoeff(&k);
        dominant_[static_cast<size_t>(v)] =
            k >= smpl22::kNumJoints ? static_cast<int>(k) - 2 : static_cast<int>(k);  // hands -> wrists
    }
}

SurfacePoint SmplBody::surface_point(int segment, double along, double around) const {
    if (segment < 0 || segment >= smpl22::kNumJoints)
        throw Error(spec_.smpl_path, "segment", "0..21", std::to_string(segment));
    const SegmentDef& d = kSegments[static_cast<size_t>(segment)];
    const int s = d.rule == TwistRule::leaf ? d.parent : segment;
    const Vector3d j0 = rest22_[static_cast<size_t>(s)], l = axes_.long_axis[static_cast<size_t>(s)];
    const double length = (rest22_[static_cast<size_t>(kSegments[static_cast<size_t>(s)].distal)] - j0).norm();
    Vector3d u, v;
    cross_section_axes(l, &u, &v);
    const Vector3d dir = std::cos(around) * u + std::sin(around) * v;
    // The segment's skin vertex closest to the wanted height along the bone and the wanted direction around it.
    double best = 1e300;
    int best_v = -1;
    for (int i = 0; i < num_vertices(); ++i) {
        if (dominant_[static_cast<size_t>(i)] != s &&
            !(d.rule == TwistRule::leaf && dominant_[static_cast<size_t>(i)] == segment))
            continue;
        const Vector3d r = shaped_.row(i).transpose() - j0;
        const double axial = r.dot(l);
        const Vector3d radial = r - axial * l;
        const double rn = radial.norm();
        if (rn <= 0) continue;
        const double score = std::fabs(axial / length - along) + (1 - radial.dot(dir) / rn);
        if (score < best) best = score, best_v = i;
    }
    if (best_v < 0)
        throw Error(spec_.smpl_path, "weights",
                    "skin vertices on segment " + std::string(smpl22::kJointNames[static_cast<size_t>(s)]));
    return {shaped_.row(best_v).transpose(), normals_.row(best_v).transpose()};
}

SurfacePoint SmplBody::vertex_point(int vertex) const {
    if (vertex < 0 || vertex >= num_vertices())
        throw Error(spec_.smpl_path, "vertex", "0.." + std::to_string(num_vertices() - 1), std::to_string(vertex));
    return {shaped_.row(vertex).transpose(), normals_.row(vertex).transpose()};
}

BodyAnchor SmplBody::anchor(int segment, const SurfacePoint& p) const {
    BodyAnchor a;
    a.segment = segment;
    Eigen::Index v = 0;
    (shaped_.rowwise() - p.position.transpose()).rowwise().squaredNorm().minCoeff(&v);
    a.vertex = static_cast<int>(v);
    a.rest_position = shaped_.row(v).transpose();
    return a;
}

void SmplBody::global_transforms(const PosedFrame& frame, std::vector<Matrix3d>* r, std::vector<Vector3d>* x) const {
    r->resize(kJoints);
    x->resize(kJoints);
    for (int k = 0; k < kJoints; ++k) {
        const size_t i = static_cast<size_t>(k);
        if (k < smpl22::kNumJoints) {
            (*r)[i] = frame.rotation[i];
            (*x)[i] = frame.joints[i];
        } else {  // hands ride on the wrists
            const size_t w = static_cast<size_t>(parents_[i]);
            (*r)[i] = (*r)[w];
            (*x)[i] = (*x)[w] + (*r)[w] * (joints_[i] - joints_[w]);
        }
    }
}

Eigen::VectorXd SmplBody::pose_feature(const std::vector<Matrix3d>& r) const {
    Eigen::VectorXd f(9 * (kJoints - 1));
    for (int k = 1; k < kJoints; ++k) {
        const Matrix3d local =
            r[static_cast<size_t>(parents_[static_cast<size_t>(k)])].transpose() * r[static_cast<size_t>(k)];
        const Matrix3d d = local - Matrix3d::Identity();
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) f[9 * (k - 1) + 3 * a + b] = d(a, b);  // row-major, as SMPL flattens
    }
    return f;
}

Vector3d SmplBody::skin(int v, const std::vector<Matrix3d>& r, const std::vector<Vector3d>& x,
                        const Eigen::VectorXd& feature) const {
    Vector3d rest = shaped_.row(v).transpose();
    for (int c = 0; c < 3; ++c) rest[c] += posedirs_.row(3 * v + c).dot(feature);
    Vector3d out = Vector3d::Zero();
    for (int k = 0; k < kJoints; ++k) {
        const double w = weights_(v, k);
        if (w == 0) continue;
        const size_t i = static_cast<size_t>(k);
        out += w * (r[i] * (rest - joints_[i]) + x[i]);
    }
    return out;
}

void SmplBody::pose_anchor(const BodyAnchor& a, const PosedFrame& frame, Vector3d* position, Matrix3d* rotation) const {
    std::vector<Matrix3d> r;
    std::vector<Vector3d> x;
    global_transforms(frame, &r, &x);
    *position = skin(a.vertex, r, x, pose_feature(r));
    // The skin's local rotation: the weight-blended joint rotations projected back onto SO(3).
    Matrix3d blend = Matrix3d::Zero();
    for (int k = 0; k < kJoints; ++k) blend += weights_(a.vertex, k) * r[static_cast<size_t>(k)];
    Eigen::JacobiSVD<Matrix3d> svd(blend, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Matrix3d u = svd.matrixU();
    if ((u * svd.matrixV().transpose()).determinant() < 0) u.col(2) *= -1;
    *rotation = u * svd.matrixV().transpose();
}

SmplBody::Matrix SmplBody::posed_vertices(const PosedFrame& frame) const {
    std::vector<Matrix3d> r;
    std::vector<Vector3d> x;
    global_transforms(frame, &r, &x);
    const Eigen::VectorXd feature = pose_feature(r);
    Matrix out(shaped_.rows(), 3);
    for (int v = 0; v < num_vertices(); ++v) out.row(v) = skin(v, r, x, feature).transpose();
    return out;
}

}  // namespace t2imu
