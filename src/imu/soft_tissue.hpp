// A sensor on soft tissue or a strap is not bolted to the bone: its attachment is a damped spring-mass on the
// body point (the wobbling-mass models of soft tissue, e.g. Gruber et al. 1998, "A comparative study of impact
// dynamics: wobbling mass model versus rigid body models", J. Biomech. 31; skin-mounted accelerometers'
// attachment resonance, Forner-Cordero et al. 2008, Gait & Posture 27).
//
// One second-order mode per direction, the same for translation and rotation: with the base (the body point,
// or the segment's rotation) accelerating by b(t), the mass's displacement u relative to the base follows
//   u'' + 2 zeta omega u' + omega^2 u = -b,        omega = 2 pi frequency_hz
// and the mass accelerates by b + u''. A base at rest or moving slowly (well below the natural frequency) drags
// the mass along with it (u'' -> 0): a static body reads gravity only. Quick changes of b make it ring at
// frequency_hz sqrt(1 - zeta^2), decaying by exp(-zeta omega t).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace t2imu {

struct SoftTissue {
    double frequency_hz = 0;   // natural frequency of the attachment (Hz); 0 = rigid (bolted to the bone)
    double damping_ratio = 0;  // zeta, 0 < zeta < 1 for an attachment that rings
    bool enabled() const { return frequency_hz > 0; }  // ranges: realism.cpp's table
};

// The rate the attachment is integrated at, at least: imu_synthesis.cpp runs it at the output rate times the
// smallest whole number that reaches this, so its step is never longer than 1 / kAttachmentRateHz.
constexpr double kAttachmentRateHz = 1000;

// How much one RK4 step of dt seconds multiplies the spring-mass's fastest free mode: max |R(lambda dt)| over
// the eigenvalues lambda = omega (-zeta ± sqrt(zeta^2 - 1)), with R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24. Above 1
// the integration grows without bound whatever the input (docs/realism.md: the stability bound).
double rk4_growth_per_step(const SoftTissue& tissue, double dt);

// The relative motion of the mass for a base acceleration sampled every dt seconds (input linear between
// samples, RK4): per sample u, u' and u'' (units of b times s^2, s, 1). Starts at rest (u = u' = 0).
struct SpringMassResponse {
    std::vector<Eigen::Vector3d> displacement, velocity, acceleration;
};
SpringMassResponse spring_mass_response(const std::vector<Eigen::Vector3d>& base_acceleration, double dt,
                                        const SoftTissue& tissue);

}  // namespace t2imu
