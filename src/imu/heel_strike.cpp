#include "imu/heel_strike.hpp"

#include <cmath>
#include <random>

#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;

double landing_transmissibility(int segment) {
    using namespace smpl22;
    switch (segment) {
        case left_knee:
        case right_knee:
        case left_ankle:
        case right_ankle:
        case left_foot:
        case right_foot: return 1.0;
        case left_hip:
        case right_hip: return 0.6;
        case pelvis: return 0.4;
        case spine1:
        case spine2: return 0.35;
        case spine3:
        case left_collar:
        case right_collar: return 0.3;
        case neck:
        case head: return 0.2;
        default: return 0.15;  // shoulders (upper arms), elbows (forearms), wrists (hands)
    }
}

ImpactPulses impact_pulses(const std::vector<Landing>& landings, double gain, double duration_s, int segment,
                           double fps, const LandingSpread& spread, uint64_t seed) {
    ImpactPulses p;
    p.duration_s = duration_s;
    p.smoothing_s = 1 / fps;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    const bool drawn = spread.size_sd > 0 || spread.horizontal_sd > 0;
    for (const Landing& l : landings) {
        p.time_s.push_back(l.time_s);
        const double up = gain * landing_transmissibility(segment);
        if (!drawn) {
            p.delta_v.push_back(Vector3d(0, up, 0));
            continue;
        }
        const double size = up * std::exp(spread.size_sd * normal(rng));
        const double x = spread.horizontal_sd * normal(rng), z = spread.horizontal_sd * normal(rng);
        p.delta_v.push_back(size * Vector3d(x, 1, z));
    }
    return p;
}

Vector3d ImpactPulses::acceleration(double t) const {
    Vector3d a = Vector3d::Zero();
    const double centre_offset = duration_s / 2;
    for (size_t i = 0; i < time_s.size(); ++i) {
        const double s = t - time_s[i];
        if (std::abs(s - centre_offset) > 5 * smoothing_s + duration_s) continue;
        const double sharp = s >= 0 && s <= duration_s ? M_PI / (2 * duration_s) * std::sin(M_PI * s / duration_s) : 0;
        const double z = (s - centre_offset) / smoothing_s;
        const double spread = std::exp(-0.5 * z * z) / (smoothing_s * std::sqrt(2 * M_PI));
        a += delta_v[i] * (sharp - spread);
    }
    return a;
}

}  // namespace t2imu
