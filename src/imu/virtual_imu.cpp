#include "imu/virtual_imu.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "body/procedural_body.hpp"
#include "body/trunk_sway.hpp"
#include "core/error.hpp"
#include "core/hash.hpp"
#include "imu/body_vibration.hpp"
#include "imu/device_rate.hpp"
#include "imu/imu_dataset.hpp"
#include "motion/foot_landings.hpp"

namespace t2imu {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

nlohmann::json vec(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

void check_motion_for_imu(const JointSequence& motion, const std::string& source) {
    if (motion.num_joints != smpl22::kNumJoints)
        throw Error(source, "shape", "[F,22,3] joints", std::to_string(motion.num_joints) + " joints");
    if (motion.num_frames < 4) throw Error(source, "frames", "at least 4 frames", std::to_string(motion.num_frames));
    if (!(motion.fps > 0)) throw Error(source, "fps", "a positive frame rate", std::to_string(motion.fps));
}

BodySpec size_body_to_motion(const JointSequence& motion) {
    const std::vector<Joints22> frames = joints22_frames(motion);
    double leg = 0;
    for (const Joints22& x : frames) leg += leg_length(x);
    leg /= static_cast<double>(frames.size());
    BodySpec b;
    b.kind = BodySpec::Kind::none;
    b.name = "none";
    b.height_m = std::clamp(ProceduralBody::stature_for_leg_length(leg), 0.6, 2.4);
    b.mass_kg = 22.0 * b.height_m * b.height_m;
    return b;
}

void sensor_track(const BodyModel& body, const FittedMotion& motion, const SensorMount& mount,
                  std::vector<Vector3d>* position, std::vector<Quat>* orientation) {
    position->resize(motion.frames.size());
    orientation->resize(motion.frames.size());
    for (size_t f = 0; f < motion.frames.size(); ++f) {
        Matrix3d r;
        body.pose_anchor(mount.anchor, motion.frames[f], &(*position)[f], &r);
        (*orientation)[f] = Quat(Matrix3d(r * mount.rest_from_sensor));
    }
}

void VirtualImuOptions::set_realism(const RealismModel& model) {
    model.validate("--realism " + model.name);
    sensor_ = parse_noise_model(model.sensor, "--realism " + model.name + ": sensor");
    realism_ = model;
}

void VirtualImuOptions::validate() const {
    if (!(rate_hz > 0 && rate_hz <= 2000)) throw Error("--rate", "rate", "0 < HZ <= 2000", std::to_string(rate_hz));
    if (realism_.sensor_sample_rate_hz > 0 && rate_hz != std::round(rate_hz))
        throw Error("--rate", "rate", "a whole number of Hz with a realism model's sensor rate",
                    std::to_string(rate_hz));
}

namespace {

// The stages of the realism chain (realism.hpp's RealismStage), each a function, in the order they run.

// motion: the realism model's edits of the motion itself, before any body: the tempo's uniform time warp (the same
// path at tempo x the speed) and the foot landings the attachment stage sharpens.
struct MotionStage {
    JointSequence timed;
    double tempo = 1;
    std::vector<Landing> landings;
};
MotionStage motion_stage(const JointSequence& motion, const RealismModel& realism, uint64_t seed) {
    MotionStage m{motion, draw_tempo(realism, seed), {}};
    m.timed.fps = motion.fps * m.tempo;
    if (realism.landings.enabled()) m.landings = detect_landings(m.timed);
    return m;
}

// body: the fitted frames a sensor on `segment` rides on: its own re-posed copy when the trunk sway turns its
// segment, else the body's fit.
const FittedMotion& body_stage(const FittedMotion& fitted, const RealismModel& realism, int segment, double fps,
                               FittedMotion* own) {
    if (!realism.trunk.enabled() || !is_trunk_segment(segment)) return fitted;
    *own = fitted;
    apply_trunk_sway(realism.trunk, segment, fps, &own->frames);
    return *own;
}

// attachment: what lies between the body point and the sensor (soft tissue, the strap's run, landing pulses).
AttachmentDynamics attachment_stage(const RealismModel& realism, const MotionStage& motion, const SensorMount& mount,
                                    uint64_t seed) {
    AttachmentDynamics d;
    d.tissue = realism.tissue;
    d.strap = realism.strap;
    d.strap_axis = mount.horizontal_tangent_in_sensor();
    if (!motion.landings.empty())
        d.impacts = impact_pulses(motion.landings, realism.landings.gain_m_s, realism.landings.duration_ms / 1000,
                                  mount.placement.segment, motion.timed.fps, realism.landings.spread, seed);
    return d;
}

}  // namespace

BodyImu synthesize_body_imu(const JointSequence& motion, const BodySpec& spec,
                            const std::vector<SensorPlacement>& sensors, const VirtualImuOptions& options) {
    options.validate();
    BodyImu out;
    const bool none = spec.kind == BodySpec::Kind::none;
    out.body = none ? size_body_to_motion(motion) : spec;
    BodySpec build = out.body;
    if (none) build.kind = BodySpec::Kind::procedural;
    const std::unique_ptr<BodyModel> body = make_body(build);
    const RealismModel& realism = options.realism();
    const auto seed = [&](const std::string& position, const char* draw) {
        return derived_seed(options.seed, {out.body.name, position, draw});
    };
    const MotionStage timed = motion_stage(motion, realism, seed("", "tempo"));
    out.tempo = timed.tempo;
    FitOptions fit;
    fit.keep_input_joints = none;
    const FittedMotion fitted = fit_body(timed.timed, *body, fit);
    out.leg_scale = fitted.leg_scale;
    out.mean_error_mm = fitted.mean_error_mm;
    out.max_error_mm = fitted.max_error_mm;
    const SensorNoiseModel& device = options.sensor_model();
    const double sample_rate = realism.sensor_sample_rate_hz > 0 ? realism.sensor_sample_rate_hz : options.rate_hz;
    std::vector<Vector3d> p;
    std::vector<Quat> q;
    for (const SensorPlacement& placement : sensors) {
        FittedMotion own;
        const FittedMotion& frames = body_stage(fitted, realism, placement.segment, timed.timed.fps, &own);
        // mount: on the skin, with the mounting error and the realism model's tilt.
        out.mount_tilts_deg.push_back(draw_tilt_deg(realism, seed(placement.position, "tilt")));
        out.mounts.push_back(mount_sensor(*body, placement, out.mount_tilts_deg.back()));
        sensor_track(*body, frames, out.mounts.back(), &p, &q);
        const AttachmentDynamics dynamics =
            attachment_stage(realism, timed, out.mounts.back(), seed(placement.position, "landings"));
        ImuSignals s = synthesize_imu(p, q, timed.timed.fps, sample_rate, dynamics);
        add_body_vibration(realism.vibration, seed(placement.position, "vibration"), &s);  // signal
        apply_sensor_noise(device, seed(placement.position, "noise"), &s);                 // device
        out.signals.push_back(resample_imu_signals(s, options.rate_hz));
    }
    return out;
}

std::vector<std::string> write_body_imu(const std::string& dir, const BodyImu& imu) {
    std::vector<std::string> paths;
    for (size_t i = 0; i < imu.mounts.size(); ++i) {
        paths.push_back(imu.body.name + "/" + imu.mounts[i].placement.position + ".csv");
        write_imu_recording(dir + "/" + paths.back(), imu.signals[i]);
    }
    return paths;
}

nlohmann::json virtual_imu_meta(const std::vector<BodyImu>& bodies, const JointSequence& motion,
                                const VirtualImuOptions& options, const std::string& input) {
    nlohmann::json meta;
    meta["input"] = input;
    meta["frames"] = motion.num_frames;
    meta["fps"] = motion.fps;
    meta["rate_hz"] = options.rate_hz;
    meta["samples"] = bodies.empty() || bodies[0].signals.empty() ? 0 : bodies[0].signals[0].t.size();
    meta["frames_note"] = "world Y up, body facing +Z; acc = specific force in the sensor frame (m/s^2), gyr in rad/s";
    meta["interpolant"] = "not-a-knot cubic spline of positions and of sign-continuous quaternions";
    meta["realism"] = options.realism().to_json();
    meta["seed"] = options.seed;
    const SensorNoiseModel& device = options.sensor_model();
    meta["noise"] = {{"model", device.name},
                     {"acc_noise_density", device.acc_noise_density},
                     {"gyr_noise_density", device.gyr_noise_density},
                     {"acc_bias_sd", device.acc_bias_sd},
                     {"gyr_bias_sd", device.gyr_bias_sd},
                     {"acc_range", device.acc_range},
                     {"gyr_range", device.gyr_range},
                     {"bits", device.bits}};
    meta["bodies"] = nlohmann::json::array();
    for (const BodyImu& b : bodies) {
        nlohmann::json body = {{"name", b.body.name},       {"height_m", b.body.height_m},
                               {"mass_kg", b.body.mass_kg}, {"sex", sex_name(b.body.sex)},
                               {"leg_scale", b.leg_scale},  {"tempo", b.tempo}};
        body["kind"] = b.body.kind == BodySpec::Kind::smpl   ? "smpl"
                       : b.body.kind == BodySpec::Kind::none ? "none"
                                                             : "procedural";
        if (b.body.kind == BodySpec::Kind::smpl) body["smpl"] = {{"path", b.body.smpl_path}, {"betas", b.body.betas}};
        nlohmann::json fit;
        double mean_all = 0;
        for (int j = 0; j < smpl22::kNumJoints; ++j) {
            fit[smpl22::kJointNames[static_cast<size_t>(j)]] = {{"mean_mm", b.mean_error_mm[static_cast<size_t>(j)]},
                                                                {"max_mm", b.max_error_mm[static_cast<size_t>(j)]}};
            mean_all += b.mean_error_mm[static_cast<size_t>(j)] / smpl22::kNumJoints;
        }
        body["fit_error_mm"] = fit;
        body["fit_error_mean_mm"] = mean_all;
        nlohmann::json placements = nlohmann::json::array();
        for (size_t k = 0; k < b.mounts.size(); ++k) {
            const SensorMount& m = b.mounts[k];
            const SensorPlacement& p = m.placement;
            nlohmann::json pj = {{"position", p.position},
                                 {"segment", smpl22::kJointNames[static_cast<size_t>(p.segment)]},
                                 {"along", p.along},
                                 {"around_deg", p.around_deg},
                                 {"note", p.note},
                                 {"axes_words", {p.axis[0], p.axis[1], p.axis[2]}},
                                 {"rest_position_m", vec(m.anchor.rest_position)},
                                 {"rest_axes",
                                  {{"x", vec(m.rest_from_sensor.col(0))},
                                   {"y", vec(m.rest_from_sensor.col(1))},
                                   {"z", vec(m.rest_from_sensor.col(2))}}}};
            if (m.anchor.vertex >= 0) pj["vertex"] = m.anchor.vertex;
            if (k < b.mount_tilts_deg.size())
                pj[realism_lever("tilt").keys[0].key] = b.mount_tilts_deg[k];  // the drawn tilt
            placements.push_back(pj);
        }
        body["placements"] = placements;
        meta["bodies"].push_back(body);
    }
    return meta;
}

}  // namespace t2imu
