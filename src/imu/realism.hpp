// The realism model: what stands between an ideal sensor bolted to a moving skeleton and a real recording,
// in levers that are each seeded, switchable and measured on their own (README, "Sensor realism").
//
//   tilt_deg, tilt_sd_deg  mounting tilt: the sensor turned about the skin's horizontal tangent so that its
//                          outward normal points down by tilt_deg (a belt below a belly, a strap on a tapering
//                          limb), drawn per recording from a normal distribution (mean, sd; degrees). No tilt
//                          where the skin faces up or down.
//   tissue_hz, tissue_damping
//                          the attachment's spring-mass (soft_tissue.hpp); 0 Hz = bolted to the bone
//   strap_hz, strap_damping
//                          the device sliding along its belt or strap (the skin's horizontal tangent at the
//                          sensor: across the belly for a belt at the front): a spring-mass in that direction
//                          only, on top of the soft tissue (imu_synthesis.hpp); 0 Hz = none
//   impact_gain, impact_ms landing transients (heel_strike.hpp): the velocity change of a landing at the shank
//                          (m/s; transmissibility scales it to the sensor's segment) and the duration of a
//                          landing (ms); gain 0 = none
//   impact_size_sd, impact_horizontal_sd
//                          how landings differ (heel_strike.hpp, LandingSpread): sd of the log of each one's
//                          size, and of its horizontal components over its vertical one; 0 = all alike, upright
//   tempo_sd               motion tempo: the motion is played at its frame rate times exp(N(0, tempo_sd)) per
//                          recording: a uniform time warp, which keeps the path and scales every speed by the
//                          same factor (1.0 leaves the motion as it is)
//   roll_gain, roll_sigma_s
//                          device roll (device_roll.hpp): the share of its segment's frontal-plane sway the device
//                          rolls with (1 = bolted; 0 = level; negative = against it) and the Gaussian sd (s)
//                          that separates sway from posture
//   trunk_pitch_gain, trunk_yaw_gain, trunk_sigma_s
//                          a device on the trunk (trunk_sway.hpp): the share of its segment's sway about the
//                          left-right axis and the long axis the device turns with (1 = bolted; 0 = the slow part
//                          only) and the Gaussian sd (s) that separates sway from heading and posture
//   vibration_gain, vibration_low_hz, vibration_high_hz
//                          body vibration (body_vibration.hpp): band-limited noise whose sd is gain x the
//                          motion's local rms level, in [low_hz, high_hz]; gain 0 = none
//   device                 the sensor's own errors: a sensor_noise.hpp model ("none", a preset, overrides)
//   device_rate_hz         the device's own sample rate (device_rate.hpp): the sensor is sampled at it, what lies
//                          above its Nyquist frequency folding into the band, and the recording is resampled to
//                          the output rate; 0 = sampled at the output rate
//
// Presets (realism.cpp gives the figures each value rests on). The ablation on the shared SisFall subjects
// (README, "Sensor realism") chose the levers: mounting tilt and the device model raised synthetic-only HAR,
// landings (and their spread), soft tissue, the strap mode, the trunk sway, body vibration, tempo and device roll
// lowered it or left it within its spread, so those are off in every preset:
//   none        everything off: the ideal sensor of the paper's pipeline
//   sisfall     the SisFall belt board at the waist: tilt calibrated on the shared SisFall subjects, device sisfall
//   umafall     UMAFall's SensorTags: tilt spread calibrated on the shared UMAFall subjects, device umafall
//   hugadb      HuGaDB's leg straps: not calibrated (the shared copy has no waist sensor), device hugadb
//   smartphone  RealWorld's phones: not calibrated (no RealWorld data), device smartphone
// A TOML file (`--realism my.toml`) names the same keys, with `base = "PRESET"` to start from a preset; an
// unknown key is refused.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "imu/body_vibration.hpp"
#include "imu/device_roll.hpp"
#include "imu/heel_strike.hpp"
#include "imu/soft_tissue.hpp"
#include "imu/trunk_sway.hpp"

namespace t2imu {

struct RealismModel {
    std::string name = "none";
    double tilt_deg = 0, tilt_sd_deg = 0;
    SoftTissue tissue;
    SoftTissue strap;
    double impact_gain = 0, impact_ms = 40;
    LandingSpread impact_spread;
    double tempo_sd = 0;
    DeviceRoll roll;
    TrunkSway trunk;
    BodyVibration vibration;
    std::string device = "none";
    double device_rate_hz = 0;

    // Throws Error naming `source` and the key for a value out of range.
    void validate(const std::string& source) const;
    nlohmann::json to_json() const;
};

const std::vector<std::string>& realism_preset_names();
RealismModel realism_preset(const std::string& name);  // errors name --realism
RealismModel parse_realism_toml(const std::string& text, const std::string& source);
// A preset name or a .toml file's path (errors name --realism or the file).
RealismModel parse_realism(const std::string& text);

// Per recording draws, deterministic in the seed.
double draw_tilt_deg(const RealismModel& model, uint64_t seed);
double draw_tempo(const RealismModel& model, uint64_t seed);

}  // namespace t2imu
