// Joints -> bodies -> virtual sensors: the whole bodies/IMU stage for one motion.
//
// For each body: fit the body to the joints (fitting.hpp), mount every placement on its skin
// (placement.hpp), follow each sensor's position and orientation through the motion, and turn those into
// accelerometer and gyroscope signals at the output rate (imu_synthesis.hpp), optionally corrupted by the
// device's errors and the realism model (realism.hpp). The realism chain runs in stages (realism.hpp's
// RealismStage), each a function of virtual_imu.cpp: motion (the tempo's time warp, the foot landings, before
// fitting), body (the trunk sway re-poses a trunk sensor's copy of the fitted frames), mount (the mounting error and
// tilt), attachment (soft tissue, the strap, landing pulses, while the signals are computed at the device's rate,
// imu_synthesis.hpp), signal (body vibration), device (the device's errors, sensor_noise.hpp, and resampling to
// the output rate, device_rate.hpp). Random parts (mounting errors, tilt, tempo, landings, vibration, noise) are
// seeded per body (and sensor) from one seed, so the output does not depend on which other bodies or sensors were
// asked for.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "body/fitting.hpp"
#include "imu/placement.hpp"
#include "imu/realism.hpp"
#include "imu/sensor_noise.hpp"

namespace t2imu {

struct VirtualImuOptions {
    double rate_hz = 50;
    uint64_t seed = 0;

    // The realism model (realism.hpp; "none" = the ideal sensor), validated, and its sensor model parsed, once here:
    // every recording after reads them. Throws Error naming --realism.
    void set_realism(const RealismModel& model);
    const RealismModel& realism() const { return realism_; }
    const SensorNoiseModel& sensor_model() const { return sensor_; }
    // Throws Error naming --rate for a rate out of range, or not whole with a realism model's sensor rate.
    void validate() const;

private:
    RealismModel realism_;
    SensorNoiseModel sensor_;
};

struct BodyImu {
    BodySpec body;  // as used: --body none is given the height and mass it was sized to
    double leg_scale = 1;
    double tempo = 1;                     // the realism model's time warp of this recording (1 = as captured)
    std::vector<double> mount_tilts_deg;  // per mount: the realism model's tilt (degrees)
    std::array<double, smpl22::kNumJoints> mean_error_mm{}, max_error_mm{};
    std::vector<SensorMount> mounts;
    std::vector<ImuSignals> signals;  // one per mount
};

// The procedural body `--body none` stands for: the input's own proportions decide its height (leg length over
// the leg's share of stature); mass at BMI 22.
BodySpec size_body_to_motion(const JointSequence& motion);

// Refuses what the synthesis cannot use, naming `source`: a joint count other than 22, fewer than 4 frames.
void check_motion_for_imu(const JointSequence& motion, const std::string& source);

BodyImu synthesize_body_imu(const JointSequence& motion, const BodySpec& body,
                            const std::vector<SensorPlacement>& sensors, const VirtualImuOptions& options);

// Sensor position (world, m) and orientation (world from sensor) in every frame of a fitted motion.
void sensor_track(const BodyModel& body, const FittedMotion& motion, const SensorMount& mount,
                  std::vector<Eigen::Vector3d>* position, std::vector<Quat>* orientation);

// The recordings of one body under `dir`, one per mount: dir/<body>/<position>.csv (imu_dataset.hpp's recording
// format). Returns their paths relative to `dir`, in mount order. t2imu imu synth writes its folder so, and t2imu
// synth each job's recordings/<job>/.
std::vector<std::string> write_body_imu(const std::string& dir, const BodyImu& imu);

// meta.json: bodies (height, mass, sex, fit error), placements with mountings, frames and rates, noise, seed.
nlohmann::json virtual_imu_meta(const std::vector<BodyImu>& bodies, const JointSequence& motion,
                                const VirtualImuOptions& options, const std::string& input);

}  // namespace t2imu
