#include "imu/soft_tissue.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace t2imu {

using Eigen::Vector3d;

double rk4_growth_per_step(const SoftTissue& tissue, double dt) {
    if (!tissue.enabled()) return 0;
    const double w = 2 * M_PI * tissue.frequency_hz, zeta = tissue.damping_ratio;
    const std::complex<double> root = std::sqrt(std::complex<double>(zeta * zeta - 1, 0));
    double growth = 0;
    for (const std::complex<double> lambda : {w * (-zeta + root), w * (-zeta - root)}) {
        const std::complex<double> z = lambda * dt;
        growth = std::max(growth, std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0));
    }
    return growth;
}

SpringMassResponse spring_mass_response(const std::vector<Vector3d>& base, double dt, const SoftTissue& tissue) {
    const size_t n = base.size();
    SpringMassResponse r;
    r.displacement.assign(n, Vector3d::Zero());
    r.velocity.assign(n, Vector3d::Zero());
    r.acceleration.assign(n, Vector3d::Zero());
    if (!tissue.enabled() || n == 0) return r;
    const double w = 2 * M_PI * tissue.frequency_hz, c = 2 * tissue.damping_ratio * w, k = w * w;
    const auto accel = [&](const Vector3d& b, const Vector3d& u, const Vector3d& v) -> Vector3d {
        return -b - c * v - k * u;
    };
    Vector3d u = Vector3d::Zero(), v = Vector3d::Zero();
    r.acceleration[0] = accel(base[0], u, v);
    for (size_t i = 1; i < n; ++i) {
        const Vector3d& b0 = base[i - 1];
        const Vector3d& b1 = base[i];
        const Vector3d bh = 0.5 * (b0 + b1);
        // RK4 on (u, v) with the input linear across the step.
        const Vector3d k1u = v, k1v = accel(b0, u, v);
        const Vector3d k2u = v + 0.5 * dt * k1v, k2v = accel(bh, u + 0.5 * dt * k1u, v + 0.5 * dt * k1v);
        const Vector3d k3u = v + 0.5 * dt * k2v, k3v = accel(bh, u + 0.5 * dt * k2u, v + 0.5 * dt * k2v);
        const Vector3d k4u = v + dt * k3v, k4v = accel(b1, u + dt * k3u, v + dt * k3v);
        u += dt / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
        v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        r.displacement[i] = u;
        r.velocity[i] = v;
        r.acceleration[i] = accel(b1, u, v);
    }
    return r;
}

}  // namespace t2imu
