// The embedded default body: an anthropometric model built from height, mass and sex alone, no external files.
//
// Skeleton: HumanML3D's target skeleton (the SMPL subject every HumanML3D motion is retargeted to, 1.70 m tall)
// scaled to the stature H, laid out standing with the arms hanging; ankles at 0.039 H and the ball of the foot at
// 0.012 H (Winter, "Biomechanics and Motor Control of Human Movement", 4th ed., 2009, Fig. 4.1). Women's hip
// span is 1.05 times and shoulder span 0.95 times the reference's, men's the reverse. Keeping HumanML3D's
// proportions means a HumanML3D motion retargets onto every body without distortion: only size, breadths and
// girths differ between bodies, as between the paper's eight SMPL shapes.
//
// Surface: every segment is an elliptic frustum around its bone: half-depth a (front-back) and half-width b
// (left-right) at the proximal end, both scaled by a taper factor at the distal end. Limbs follow the person's
// mass: each holds its share of body mass (de Leva 1996, J. Biomech. 29(9):1223-1230, Table 4, male and
// female columns) at a uniform density of 1050 kg/m^3 (Dempster 1955), so a heavier body of the same height
// has thicker limbs. Trunk sections come from typical breadths and depths as fractions of stature, their
// areas scaled by BMI / 22. Depth/width ratios and tapers are fixed shape constants (tables in the .cpp).
//
// Angles about a segment: 0 = front (the rest direction +Z, projected across the segment), +90 degrees = the
// body's left (+X), 180 = back, -90 = right; for the collars, which run sideways, +90 degrees is up.
#pragma once
#include <array>

#include "body/body_model.hpp"

namespace t2imu {

struct SegmentShape {
    double length = 0;      // m, proximal joint to distal joint (to the vertex for the head and neck)
    double half_depth = 0;  // a at the proximal end, m
    double half_width = 0;  // b at the proximal end, m
    double taper = 1;       // distal radii / proximal radii
    double mass_kg = 0;     // a limb's share of body mass (0 for trunk, head and collars)
};

class ProceduralBody : public BodyModel {
public:
    explicit ProceduralBody(const BodySpec& spec);

    const BodySpec& spec() const override { return spec_; }
    const Joints22& rest_joints() const override { return rest_; }
    SurfacePoint surface_point(int segment, double along, double around) const override;
    SurfacePoint vertex_point(int vertex) const override;
    BodyAnchor anchor(int segment, const SurfacePoint& p) const override;
    void pose_anchor(const BodyAnchor& a, const PosedFrame& frame, Eigen::Vector3d* position,
                     Eigen::Matrix3d* rotation) const override;

    const SegmentShape& shape(int segment) const { return shapes_[static_cast<size_t>(segment)]; }
    double vertex_height() const;  // top of the head in the rest pose, m (= the spec's height)
    // The stature whose skeleton has this hip-knee-ankle length (m): sizes a body to a motion.
    static double stature_for_leg_length(double leg_m);
    double limb_volume_m3() const;              // the limb frusta together (they hold their de Leva mass shares)
    static constexpr double kDensity = 1050.0;  // kg/m^3

private:
    BodySpec spec_;
    Joints22 rest_;
    RestAxes axes_;
    std::array<SegmentShape, smpl22::kNumJoints> shapes_;
};

}  // namespace t2imu
