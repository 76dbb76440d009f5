#include "body/procedural_body.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

using namespace smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// The skeleton is HumanML3D's target skeleton (smpl22::kTargetOffsets, the SMPL subject every HumanML3D motion
// is retargeted to) scaled to stature: its leg (hip-knee-ankle 0.826 m) with Winter's ankle height 0.039 H puts
// the hip joints at 0.525 H for a 1.70 m person, Winter's 0.530 H within 0.005 H, so 1.70 m is its stature.
constexpr double kReferenceStature = 1.70;
constexpr double kAnkleHeight = 0.039, kBallHeight = 0.012;  // fractions of stature (Winter 2009, Fig. 4.1)

struct SexFractions {
    double hip_width, shoulder_width;  // breadth factors on the reference skeleton's hip and shoulder spans
    // de Leva (1996) Table 4, % of body mass.
    double head, upper_trunk, middle_trunk, lower_trunk, upper_arm, forearm, hand, thigh, shank, foot;
};
// Women's pelvis is relatively wider and their shoulders narrower than men's (breadth factors 0.95 and 1.05 each way).
constexpr SexFractions kMale = {0.97, 1.03, 6.94, 15.96, 16.33, 11.17, 2.71, 1.62, 0.61, 14.16, 4.33, 1.37};
constexpr SexFractions kFemale = {1.05, 0.95, 6.68, 15.45, 14.65, 12.47, 2.55, 1.38, 0.56, 14.78, 4.81, 1.29};

// Depth/width ratio and distal/proximal taper of each limb's frustum.
struct Form {
    double depth_over_width, taper;
};
Form limb_form(int s) {
    switch (s) {
        case left_hip:
        case right_hip: return {1.0, 0.65};  // thigh
        case left_knee:
        case right_knee: return {1.0, 0.55};  // shank
        case left_ankle:
        case right_ankle: return {0.55, 0.85};  // foot: flat
        case left_shoulder:
        case right_shoulder: return {1.0, 0.80};
        default: return {0.75, 0.70};  // forearm: flatter at the wrist
    }
}

double limb_mass_percent(int s, const SexFractions& m) {
    switch (s) {
        case left_hip:
        case right_hip: return m.thigh;
        case left_knee:
        case right_knee: return m.shank;
        case left_ankle:
        case right_ankle: return m.foot;
        case left_shoulder:
        case right_shoulder: return m.upper_arm;
        case left_elbow:
        case right_elbow: return m.forearm + m.hand;
        default: return 0;
    }
}

// Trunk and head sections (half-width, half-depth as fractions of stature) of a body with BMI 22: the trunk
// holds organs of irregular density, so its size is set from typical adult breadths and depths (rounded
// survey-scale magnitudes: hip breadth ~0.19 H, waist depth ~0.12 H, chest depth ~0.14 H) rather than from
// its mass; section areas then grow in proportion to BMI / 22.
struct Section {
    double half_width, half_depth, taper;
};
Section trunk_section(int s, Sex sex) {
    const bool f = sex == Sex::female;
    switch (s) {
        case pelvis: return {f ? 0.1025 : 0.0955, 0.065, 1.0};
        case spine1: return {f ? 0.080 : 0.0825, 0.060, 1.05};
        case spine2: return {f ? 0.085 : 0.0875, 0.0675, 1.05};
        case spine3: return {f ? 0.0875 : 0.095, 0.070, 0.85};
        case neck: return {0.045, 0.055, 1.0};  // head and neck; the head's size does not follow BMI
        default: return {0.026, 0.026, 1.0};    // collars: a shoulder's thickness
    }
}

double bone(int j) { return kTargetOffsets[static_cast<size_t>(j)].norm(); }
double mean_bone(int left, int right) { return (bone(left) + bone(right)) / 2; }

// Standing, facing +Z, arms hanging; bone lengths are the reference's times H / 1.70 and laid out in
// anatomical directions (the reference's own rest directions are HumanML3D's axis-aligned raw offsets).
Joints22 rest_skeleton(double H, const SexFractions& m) {
    const double s = H / kReferenceStature;
    const Vector3d up = Vector3d::UnitY();
    Joints22 x;
    const double leg = mean_bone(left_knee, right_knee) + mean_bone(left_ankle, right_ankle);
    x[pelvis] = {0, kAnkleHeight * H + leg * s, 0};
    x[spine1] = x[pelvis] + bone(spine1) * s * up;
    x[spine2] = x[spine1] + bone(spine2) * s * up;
    x[spine3] = x[spine2] + bone(spine3) * s * up;
    x[neck] = x[spine3] + bone(neck) * s * up;
    x[head] = x[neck] + bone(head) * s * up;
    for (int side = 0; side < 2; ++side) {
        const double sx = side == 0 ? 1.0 : -1.0;  // left is +X
        const int h = side == 0 ? left_hip : right_hip, k = side == 0 ? left_knee : right_knee;
        const int a = side == 0 ? left_ankle : right_ankle, f = side == 0 ? left_foot : right_foot;
        const int c = side == 0 ? left_collar : right_collar, sh = side == 0 ? left_shoulder : right_shoulder;
        const int e = side == 0 ? left_elbow : right_elbow, w = side == 0 ? left_wrist : right_wrist;
        x[h] = x[pelvis] + sx * mean_bone(left_hip, right_hip) * s * m.hip_width * Vector3d::UnitX();
        x[k] = x[h] - mean_bone(left_knee, right_knee) * s * up;
        x[a] = x[k] - mean_bone(left_ankle, right_ankle) * s * up;
        const double foot = mean_bone(left_foot, right_foot) * s, drop = (kAnkleHeight - kBallHeight) * H;
        x[f] = x[a] + Vector3d(0, -drop, std::sqrt(std::max(foot * foot - drop * drop, 0.0)));
        // The collar bone rises towards the shoulder; the shoulder joint lies out to the side and a little lower.
        x[c] = x[spine3] + mean_bone(left_collar, right_collar) * s * Vector3d(sx * 0.45, 0.89, 0).normalized();
        x[sh] = x[c] +
                mean_bone(left_shoulder, right_shoulder) * s * m.shoulder_width * Vector3d(sx, -0.15, 0).normalized();
        x[e] = x[sh] - mean_bone(left_elbow, right_elbow) * s * up;
        x[w] = x[e] - mean_bone(left_wrist, right_wrist) * s * up;
    }
    return x;
}

}  // namespace

ProceduralBody::ProceduralBody(const BodySpec& spec) : spec_(spec) {
    if (!(spec.height_m > 0.5 && spec.height_m < 2.5))
        throw Error("body " + spec.name, "height", "0.5 to 2.5 m", std::to_string(spec.height_m));
    if (!(spec.mass_kg > 10 && spec.mass_kg < 300))
        throw Error("body " + spec.name, "mass", "10 to 300 kg", std::to_string(spec.mass_kg));
    const double H = spec.height_m;
    const SexFractions& m = spec.sex == Sex::male ? kMale : kFemale;
    rest_ = rest_skeleton(H, m);
    if (rest_[head].y() >= H) throw Error("body " + spec.name, "height", "a head joint below the vertex");
    axes_ = rest_axes(rest_);
    double percent_sum = 0;  // de Leva's columns sum to 100 +- 0.01 after rounding
    for (int k = 0; k < kNumJoints; ++k) percent_sum += limb_mass_percent(k, m);
    percent_sum += m.head + m.upper_trunk + m.middle_trunk + m.lower_trunk;
    const double bmi_area = spec.mass_kg / (H * H) / 22.0;
    for (int s = 0; s < kNumJoints; ++s) {
        SegmentShape& shape = shapes_[static_cast<size_t>(s)];
        const SegmentDef& d = kSegments[static_cast<size_t>(s)];
        if (d.rule == TwistRule::leaf) continue;
        shape.length = s == neck ? H - rest_[neck].y()
                                 : (rest_[static_cast<size_t>(d.distal)] - rest_[static_cast<size_t>(s)]).norm();
        const double percent = limb_mass_percent(s, m);
        if (percent > 0) {
            // Frustum volume pi a b L (1 + k + k^2) / 3 with a = r b holds the limb's mass at kDensity.
            const Form form = limb_form(s);
            const double k = form.taper, frustum = (1 + k + k * k) / 3.0;
            shape.mass_kg = spec.mass_kg * percent / percent_sum;
            shape.taper = k;
            shape.half_width =
                std::sqrt(shape.mass_kg / kDensity / (M_PI * form.depth_over_width * shape.length * frustum));
            shape.half_depth = form.depth_over_width * shape.half_width;
        } else {
            const Section sec = trunk_section(s, spec.sex);
            const double grow = (s == neck || s == left_collar || s == right_collar) ? 1.0 : std::sqrt(bmi_area);
            shape.taper = sec.taper;
            shape.half_width = sec.half_width * H * grow;
            shape.half_depth = sec.half_depth * H * grow;
        }
    }
}

double ProceduralBody::stature_for_leg_length(double leg_m) {
    const double leg = mean_bone(left_knee, right_knee) + mean_bone(left_ankle, right_ankle);
    return leg_m / leg * kReferenceStature;
}

double ProceduralBody::vertex_height() const { return rest_[neck].y() + shapes_[neck].length; }

double ProceduralBody::limb_volume_m3() const {
    double v = 0;
    for (int s = 0; s < kNumJoints; ++s) {
        const SegmentShape& sh = shapes_[static_cast<size_t>(s)];
        if (sh.mass_kg <= 0) continue;  // trunk, head, collars and leaves
        const double k = sh.taper;
        v += M_PI * sh.half_depth * sh.half_width * sh.length * (1 + k + k * k) / 3.0;
    }
    return v;
}

SurfacePoint ProceduralBody::surface_point(int segment, double along, double around) const {
    if (segment < 0 || segment >= kNumJoints)
        throw Error("body " + spec_.name, "segment", "0..21", std::to_string(segment));
    // Leaves carry no surface of their own: a point on a leaf is a point on its parent's frustum.
    if (kSegments[static_cast<size_t>(segment)].rule == TwistRule::leaf)
        segment = kSegments[static_cast<size_t>(segment)].parent;
    const size_t s = static_cast<size_t>(segment);
    const SegmentShape& sh = shapes_[s];
    const Vector3d l = axes_.long_axis[s];
    Vector3d u, v;
    cross_section_axes(l, &u, &v);
    const double scale = 1 + (sh.taper - 1) * std::clamp(along, 0.0, 1.0);
    const double a = sh.half_depth * scale, b = sh.half_width * scale;
    const double c = std::cos(around), sn = std::sin(around);
    const double length = s == neck ? sh.length : (rest_[static_cast<size_t>(kSegments[s].distal)] - rest_[s]).norm();
    SurfacePoint p;
    p.position = rest_[s] + along * length * l + a * c * u + b * sn * v;
    p.normal = (c / a * u + sn / b * v).normalized();  // gradient of the ellipse; the taper's slope is ignored
    return p;
}

SurfacePoint ProceduralBody::vertex_point(int vertex) const {
    throw Error("body " + spec_.name, "vertex " + std::to_string(vertex),
                "an SMPL body (procedural bodies have no vertices)");
}

BodyAnchor ProceduralBody::anchor(int segment, const SurfacePoint& p) const {
    BodyAnchor a;
    a.segment = segment;
    a.rest_position = p.position;
    return a;
}

void ProceduralBody::pose_anchor(const BodyAnchor& a, const PosedFrame& frame, Vector3d* position,
                                 Matrix3d* rotation) const {
    const size_t s = static_cast<size_t>(a.segment);
    const Matrix3d& r = frame.rotation[s];
    *position = frame.joints[s] + r * (a.rest_position - rest_[s]);
    *rotation = r;
}

}  // namespace t2imu
