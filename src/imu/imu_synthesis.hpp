// Virtual IMU signals from a sensor's pose over time (after Uhlenberg et al., as in Häusler et al.).
//
// Frames: the world is Y up (HumanML3D), g = (0, -9.81, 0) m/s^2. A sensor's orientation R(t) (a quaternion q)
// maps sensor coordinates to world coordinates. Then
//   accelerometer  a = R^T (p'' - g)           specific force in the sensor frame (m/s^2): a sensor at rest reads
//                                              +9.81 along whichever of its axes points up
//   gyroscope      w = 2 vec(q^* (x) q')       angular velocity in the sensor frame (rad/s)
// p'' and q' come from cubic splines through the motion's samples (cubic_spline.hpp), evaluated at the output
// rate; q is made sign-continuous first, and the spline of q is renormalised (and differentiated as such).
//
// With attachment dynamics (soft_tissue.hpp, heel_strike.hpp) the splines are evaluated at an internal rate of
// at least 1 kHz (a multiple of rate_hz); landing pulses are added to the body point's acceleration, the
// attachment's spring-mass is run on that acceleration (translation) and on the segment's angular acceleration
// in the sensor frame (rotation, small angles: the wobble angle d turns the specific force by -d x a and adds d'
// to the gyroscope); a strap mode (a device that slides along its belt or strap) is a second spring-mass, run on
// the component along one sensor axis of the acceleration the first one gives, whose relative acceleration is
// added along that axis (translation only: the measured belt board's gyroscope shows no such rocking,
// docs/realism.md on the belt's strap; the terms of the sensor frame's rotation during a ring of a few tenths of
// a second are left out); each output sample is the mean of the internal samples within half an output period of it (a
// box filter: a sensor's and a data set's own low-pass before decimation).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "imu/heel_strike.hpp"
#include "imu/soft_tissue.hpp"
#include "motion/quaternion.hpp"

namespace t2imu {

constexpr double kGravity = 9.81;  // m/s^2, the value the paper's pipeline uses

struct ImuSignals {
    double rate_hz = 0;
    std::vector<double> t;             // seconds from the first motion frame
    std::vector<Eigen::Vector3d> acc;  // m/s^2, sensor frame, gravity included
    std::vector<Eigen::Vector3d> gyr;  // rad/s, sensor frame
};

// Specific force in the sensor frame for a world acceleration (m/s^2) and orientation (world from sensor).
Eigen::Vector3d specific_force(const Quat& world_from_sensor, const Eigen::Vector3d& acceleration_world);

// What lies between the body point and the sensor: off (the default) = a sensor bolted to the bone.
struct AttachmentDynamics {
    SoftTissue tissue;
    SoftTissue strap;                                      // along strap_axis only
    Eigen::Vector3d strap_axis = Eigen::Vector3d::Zero();  // unit, sensor frame; zero = no strap mode
    ImpactPulses impacts;                                  // no landings = none
    bool strap_enabled() const { return strap.enabled() && strap_axis.squaredNorm() > 0; }
    bool enabled() const { return tissue.enabled() || strap_enabled() || !impacts.time_s.empty(); }
};

// position[f] (metres, world) and orientation[f] (world from sensor) at `fps`; at least 4 frames. Samples at
// k / rate_hz for every k within the motion's duration.
ImuSignals synthesize_imu(const std::vector<Eigen::Vector3d>& position, const std::vector<Quat>& orientation,
                          double fps, double rate_hz, const AttachmentDynamics& dynamics = {});

}  // namespace t2imu
