#include "imu/imu_synthesis.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/signal/cubic_spline.hpp"

namespace t2imu {

Eigen::Vector3d specific_force(const Quat& world_from_sensor, const Eigen::Vector3d& acceleration_world) {
    const Eigen::Vector3d g(0, -kGravity, 0);
    return world_from_sensor.conjugate() * (acceleration_world - g);
}

namespace {

// The world acceleration of the body point (m/s^2) and the orientation with its angular velocity in the sensor
// frame (rad/s) at time t.
struct SplinePose {
    Eigen::Vector3d acceleration, angular_velocity;
    Quat orientation;
};

SplinePose evaluate_pose(const CubicSpline& ps, const CubicSpline& qs, double t) {
    Eigen::VectorXd pa, qv, qd;
    ps.evaluate(t, nullptr, nullptr, &pa);
    qs.evaluate(t, &qv, &qd, nullptr);
    const double norm = qv.norm();
    const Eigen::Vector4d u = qv / norm;
    const Eigen::Vector4d du = (qd - u * u.dot(qd)) / norm;  // d/dt (q / |q|)
    const Quat r(u[0], u[1], u[2], u[3]), dr(du[0], du[1], du[2], du[3]);
    return {pa.head<3>(), 2.0 * (r.conjugate() * dr).vec(), r};
}

// The sensor on its attachment, at an internal rate, then box-filtered down to rate_hz (see the header).
void synthesize_attached(const CubicSpline& ps, const CubicSpline& qs, double rate_hz, const AttachmentDynamics& dyn,
                         ImuSignals* out) {
    const int over = static_cast<int>(std::ceil(kAttachmentRateHz / rate_hz));
    const double dt = 1 / (rate_hz * over);
    const size_t n = static_cast<size_t>(std::floor(ps.duration() / dt + 1e-9)) + 1;
    std::vector<Eigen::Vector3d> acc(n), omega(n), alpha(n);
    std::vector<Quat> rot(n);
    for (size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) * dt;
        const SplinePose pose = evaluate_pose(ps, qs, t);
        acc[i] = pose.acceleration + dyn.impacts.acceleration(t);
        omega[i] = pose.angular_velocity;
        rot[i] = pose.orientation;
    }
    for (size_t i = 0; i < n; ++i) {
        const size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
        alpha[i] = b > a ? Eigen::Vector3d((omega[b] - omega[a]) / (static_cast<double>(b - a) * dt))
                         : Eigen::Vector3d::Zero();
    }
    const SpringMassResponse shift = spring_mass_response(acc, dt, dyn.tissue),
                             turn = spring_mass_response(alpha, dt, dyn.tissue);
    std::vector<Eigen::Vector3d> along_strap(dyn.strap_enabled() ? n : 0);
    for (size_t i = 0; i < along_strap.size(); ++i)
        along_strap[i] = dyn.strap_axis * dyn.strap_axis.dot(rot[i].conjugate() * (acc[i] + shift.acceleration[i]));
    const SpringMassResponse slide = spring_mass_response(along_strap, dt, dyn.strap);  // sensor frame
    const size_t samples = static_cast<size_t>(std::floor(ps.duration() * rate_hz + 1e-9)) + 1;
    const long half = over / 2;
    for (size_t k = 0; k < samples; ++k) {
        const long centre = static_cast<long>(k) * over;
        Eigen::Vector3d f = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
        int count = 0;
        for (long i = std::max(0L, centre - half); i <= std::min(static_cast<long>(n) - 1, centre + half);
             ++i, ++count) {
            const size_t s = static_cast<size_t>(i);
            Eigen::Vector3d force = specific_force(rot[s], acc[s] + shift.acceleration[s]);
            if (!along_strap.empty()) force += slide.acceleration[s];
            f += force - turn.displacement[s].cross(force);
            w += omega[s] + turn.velocity[s];
        }
        out->t.push_back(static_cast<double>(k) / rate_hz);
        out->acc.push_back(f / count);
        out->gyr.push_back(w / count);
    }
}

}  // namespace

ImuSignals synthesize_imu(const std::vector<Eigen::Vector3d>& position, const std::vector<Quat>& orientation,
                          double fps, double rate_hz, const AttachmentDynamics& dynamics) {
    const size_t n = position.size();
    if (n < 4) throw Error("imu", "frames", "at least 4 motion frames", std::to_string(n));
    if (orientation.size() != n)
        throw Error("imu", "orientation", std::to_string(n) + " frames", std::to_string(orientation.size()));
    if (!(fps > 0) || !(rate_hz > 0)) throw Error("imu", "rate", "positive frame and sample rates");
    CubicSpline::Samples p(static_cast<Eigen::Index>(n), 3), q(static_cast<Eigen::Index>(n), 4);
    Quat previous = orientation[0];
    for (size_t f = 0; f < n; ++f) {
        if (!position[f].allFinite() || !orientation[f].coeffs().allFinite())
            throw Error("imu", "frame " + std::to_string(f), "finite positions and orientations");
        Quat cur = orientation[f].normalized();
        if (cur.coeffs().dot(previous.coeffs()) < 0) cur.coeffs() *= -1.0;  // one continuous branch
        previous = cur;
        p.row(static_cast<Eigen::Index>(f)) = position[f].transpose();
        q.row(static_cast<Eigen::Index>(f)) << cur.w(), cur.x(), cur.y(), cur.z();
    }
    const double dt = 1.0 / fps;
    const CubicSpline ps(p, dt), qs(q, dt);
    ImuSignals out;
    out.rate_hz = rate_hz;
    if (dynamics.enabled()) {
        synthesize_attached(ps, qs, rate_hz, dynamics, &out);
        return out;
    }
    const size_t samples = static_cast<size_t>(std::floor(ps.duration() * rate_hz + 1e-9)) + 1;
    for (size_t k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) / rate_hz;
        const SplinePose pose = evaluate_pose(ps, qs, t);
        out.t.push_back(t);
        out.acc.push_back(specific_force(pose.orientation, pose.acceleration));
        out.gyr.push_back(pose.angular_velocity);
    }
    return out;
}

}  // namespace t2imu
