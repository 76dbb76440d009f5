// Heel-strike transients that a 20 fps motion cannot hold, restored as short acceleration pulses.
//
// When a foot lands, the ground stops it within some 30-50 ms and a shock runs up the body: a sharp upward
// acceleration of the shank, attenuated on its way to the trunk and head (peak accelerations in walking and
// running: tibia 2-5 g, lower back about 1 g, head 0.5-1 g; e.g. Lafortune, Lake & Hennig 1996, "Differential
// shock transmission response of the human body to impact severity and lower limb posture", J. Biomech. 29).
// A motion at 20 fps (a frame every 50 ms) keeps the velocity change of the landing but spreads it over
// several frames. Per landing we add what was lost: a half-sine pulse of `duration_s` minus a Gaussian of the
// same area and centre with the sd of one frame (what the frames hold), both carrying the upward velocity
// change delta_v. The difference has zero area and zero first moment, so the body's velocity and path are
// unchanged; only the sharpness of the landing comes back. It is what sets a sensor's attachment ringing
// (soft_tissue.hpp).
//
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "motion/foot_landings.hpp"

namespace t2imu {

// The share of the shank's landing transient that reaches a sensor on the segment of proximal joint `segment`
// (SMPL-22): 1 foot and shank, 0.6 thigh, 0.4 pelvis, 0.35 spine, 0.3 chest and shoulders, 0.2 neck and head,
// 0.15 arms. Approximate ratios of the peak accelerations in the literature above.
double landing_transmissibility(int segment);

// Landings are not all alike: each one's size is drawn log-normal about the gain (sd of its logarithm), and
// the shock reaching the sensor is not purely vertical (heel strike's braking and mediolateral impulse, a strap
// rocking on soft tissue): each landing gets horizontal components, world X and Z, drawn normal with an sd of
// horizontal_sd times its vertical one. Zero spreads: every landing straight up and of the same size.
struct LandingSpread {
    double size_sd = 0;
    double horizontal_sd = 0;
};

struct ImpactPulses {
    std::vector<double> time_s;            // per landing: contact time (s)
    std::vector<Eigen::Vector3d> delta_v;  // per landing: velocity change at the sensor (m/s, world, Y up)
    double duration_s = 0.04;              // the sharp landing
    double smoothing_s = 0.05;             // the frames' spread: one frame period
    // The extra world acceleration (m/s^2, Y up) at time t (s).
    Eigen::Vector3d acceleration(double t) const;
};

// Pulses for a sensor on `segment`: delta_v = gain (m/s at the shank) x transmissibility upwards, spread as
// above with draws from `seed` in landing order; smoothing = 1 / fps.
ImpactPulses impact_pulses(const std::vector<Landing>& landings, double gain, double duration_s, int segment,
                           double fps, const LandingSpread& spread = {}, uint64_t seed = 0);

}  // namespace t2imu
