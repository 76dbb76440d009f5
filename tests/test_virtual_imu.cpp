// Virtual IMUs on fitted bodies: physics with known answers through the whole stage (fit, mount, synthesise).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "body/procedural_body.hpp"
#include "core/error.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/mocap_import.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// The rest skeleton of `body`, moved rigidly: frame f gets rotation(t) and translation(t), t = f / fps.
template <class Motion>
JointSequence rigid_motion(const BodyModel& body, double seconds, Motion motion, double fps = 20) {
    const int frames = static_cast<int>(seconds * fps) + 1;
    JointSequence seq(frames, kNumJoints, fps);
    for (int f = 0; f < frames; ++f) {
        Matrix3d r;
        Vector3d t;
        motion(f / fps, r, t);
        for (int j = 0; j < kNumJoints; ++j) seq.at(f, j) = r * body.rest_joints()[j] + t;
    }
    return seq;
}

const BodySpec& average_man() { return paper_bodies()[2]; }

}  // namespace

TEST(VirtualImu, StandingBodyReadsGravityOnEachSensorsUpAxis) {
    const ProceduralBody body(average_man());
    const JointSequence still = rigid_motion(body, 2.0, [](double, Matrix3d& r, Vector3d& t) {
        r.setIdentity();
        t.setZero();
    });
    std::vector<SensorPlacement> sensors = parse_sensor_sets("realworld");
    for (SensorPlacement p : parse_sensor_sets("hugadb")) {
        p.position = "hugadb_" + p.position;
        sensors.push_back(p);
    }
    const BodyImu imu = synthesize_body_imu(still, average_man(), sensors, {});
    EXPECT_NEAR(imu.leg_scale, 1.0, 1e-12);
    for (size_t i = 0; i < sensors.size(); ++i) {
        const std::string& name = sensors[i].position;
        for (size_t k = 0; k < imu.signals[i].t.size(); ++k) {
            const Vector3d& a = imu.signals[i].acc[k];
            EXPECT_NEAR(a.norm(), kGravity, 1e-9) << name;
            EXPECT_LT(imu.signals[i].gyr[k].norm(), 1e-9) << name;
            // Phones stand upright (y up; along the limb on shin, thigh and upper arm); HuGaDB's x points
            // down the leg, so it reads -g, as the real recordings do while standing.
            if (name.find("forearm") != std::string::npos) {
                EXPECT_NEAR(a.x(), -kGravity, 1e-9) << name;
            } else if (i < 7) {
                EXPECT_NEAR(a.y(), kGravity, 1e-9) << name;
            } else if (name.find("foot") == std::string::npos) {
                EXPECT_NEAR(a.x(), -kGravity, 1e-9) << name;
            }
        }
    }
}

TEST(VirtualImu, TurningInPlaceGivesTheYawRateAndCentripetalForce) {
    const double w = 1.2;  // rad/s about the vertical
    const ProceduralBody body(average_man());
    const JointSequence turn = rigid_motion(body, 4.0, [&](double t, Matrix3d& r, Vector3d& x) {
        r = AngleAxisd(w * t, Vector3d::UnitY()).toRotationMatrix();
        x.setZero();
    });
    const std::vector<SensorPlacement> sensors = parse_sensor_sets("realworld");
    const BodyImu imu = synthesize_body_imu(turn, average_man(), sensors, {});
    for (size_t i = 0; i < sensors.size(); ++i) {
        const ImuSignals& s = imu.signals[i];
        const Vector3d p = imu.mounts[i].anchor.rest_position;
        const double radius = Vector3d(p.x(), 0, p.z()).norm();  // distance from the turning axis (x = z = 0)
        for (size_t k = 0; k < s.t.size(); ++k) {
            EXPECT_NEAR(s.gyr[k].norm(), w, 3e-3) << sensors[i].position;
            // Specific force: gravity plus the centripetal w^2 r towards the axis, so |a|^2 = g^2 + (w^2 r)^2.
            EXPECT_NEAR(s.acc[k].norm(), std::hypot(kGravity, w * w * radius), 5e-3) << sensors[i].position;
        }
        // The gyroscope sees the vertical in its own frame: the same direction gravity shows.
        const Vector3d g_dir = imu.mounts[i].rest_from_sensor.transpose() * Vector3d::UnitY();
        EXPECT_LT((s.gyr[s.t.size() / 2] / w - g_dir).norm(), 3e-3) << sensors[i].position;
    }
}

TEST(VirtualImu, BouncingBodyGivesTheAnalyticSpecificForce) {
    const double A = 0.04, om = 2 * M_PI * 1.5;
    const ProceduralBody body(average_man());
    const JointSequence bounce = rigid_motion(body, 3.0, [&](double t, Matrix3d& r, Vector3d& x) {
        r.setIdentity();
        x = Vector3d(0, A * std::sin(om * t), 0);
    });
    const BodyImu imu = synthesize_body_imu(bounce, average_man(), parse_sensor_sets("sisfall"), {});
    const ImuSignals& s = imu.signals[0];  // waist, y points down
    double worst = 0, worst_interior = 0;
    for (size_t k = 0; k < s.t.size(); ++k) {
        const double expected = -(kGravity - A * om * om * std::sin(om * s.t[k]));
        const double e = std::fabs(s.acc[k].y() - expected);
        worst = std::max(worst, e);
        if (s.t[k] > 0.25 && s.t[k] < 2.75) worst_interior = std::max(worst_interior, e);
    }
    // Of 3.55 m/s^2 peak: a cubic spline's second derivative errs by about A w^4 h^2 / 12 = 0.066 m/s^2 here.
    EXPECT_LT(worst_interior, 0.08);
    EXPECT_LT(worst, 0.3);  // the clip edges: no spike, only the end conditions' larger error
}

TEST(VirtualImu, ConstantVelocityGivesGravityOnlyAndRetargetingScalesIt) {
    const ProceduralBody tall(paper_bodies()[0]);
    const JointSequence glide = rigid_motion(tall, 2.0, [](double t, Matrix3d& r, Vector3d& x) {
        r.setIdentity();
        x = Vector3d(0.8 * t, 0, 1.3 * t);
    });
    // Retargeted onto a short body the trajectory is scaled, still at constant velocity: gravity only.
    const BodyImu imu = synthesize_body_imu(glide, paper_bodies()[5], parse_sensor_sets("umafall"), {});
    EXPECT_NEAR(imu.leg_scale, 1.5 / 2.0, 1e-12);
    for (const ImuSignals& s : imu.signals)
        for (size_t k = 0; k < s.t.size(); ++k) {
            EXPECT_NEAR(s.acc[k].norm(), kGravity, 1e-9);
            EXPECT_LT(s.gyr[k].norm(), 1e-9);
        }
}

TEST(VirtualImu, RefusesUnusableMotions) {
    JointSequence three(3, kNumJoints, 20);
    EXPECT_THROW(check_motion_for_imu(three, "m.npy"), Error);
    JointSequence wrong(10, 24, 20);
    EXPECT_THROW(check_motion_for_imu(wrong, "m.npy"), Error);
}

TEST(VirtualImu, NoneBodyKeepsTheInputSkeletonAndSizesItself) {
    const ProceduralBody body(paper_bodies()[4]);  // female tall, 1.80 m
    const JointSequence still = rigid_motion(body, 1.0, [](double, Matrix3d& r, Vector3d& t) {
        r.setIdentity();
        t.setZero();
    });
    const BodySpec sized = size_body_to_motion(still);
    EXPECT_NEAR(sized.height_m, 1.80, 1e-9);
    const BodyImu imu = synthesize_body_imu(still, parse_body_specs("none")[0], parse_sensor_sets("sisfall"), {});
    for (int j = 0; j < kNumJoints; ++j) EXPECT_EQ(imu.max_error_mm[j], 0.0);
    EXPECT_NEAR(imu.signals[0].acc[0].y(), -kGravity, 1e-9);
}

TEST(VirtualImu, SeveralFullTurnsKeepOneQuaternionBranch) {
    // 3 rad/s for 6 s = 2.9 turns: every orientation passes through q and -q territory; the gyroscope must
    // stay at the yaw rate throughout (a sign flip would show as a spike of ~2/dt rad/s).
    const double w = 3.0;
    const ProceduralBody body(average_man());
    const JointSequence spin = rigid_motion(body, 6.0, [&](double t, Matrix3d& r, Vector3d& x) {
        r = AngleAxisd(w * t, Vector3d::UnitY()).toRotationMatrix();
        x.setZero();
    });
    const BodyImu imu = synthesize_body_imu(spin, average_man(), parse_sensor_sets("umafall"), {});
    for (const ImuSignals& s : imu.signals)
        for (const Vector3d& g : s.gyr) EXPECT_NEAR(g.norm(), w, 0.02);
}

TEST(VirtualImu, RealWalkHasNoSpikesAtTheClipEdges) {
    // The example walk from its second frame (its first frame holds the arms in a different pose, a jump of
    // 50 degrees at the shoulder in one frame: a property of the recording, not of the synthesis).
    const JointSequence full = import_motion(std::string(T2IMU_SOURCE_DIR) + "/examples/cmu_07_05_slow_walk.bvh");
    JointSequence walk(full.num_frames - 1, kNumJoints, full.fps);
    std::copy(full.positions.begin() + kNumJoints, full.positions.end(), walk.positions.begin());
    VirtualImuOptions o;
    o.rate_hz = 100;
    const BodyImu imu = synthesize_body_imu(walk, average_man(), parse_sensor_sets("realworld"), o);
    for (size_t i = 0; i < imu.signals.size(); ++i) {
        const ImuSignals& s = imu.signals[i];
        const size_t n = s.t.size(), margin = 25;  // 0.25 s at each end
        double interior_acc = 0, interior_gyr = 0, edge_acc = 0, edge_gyr = 0;
        for (size_t k = 0; k < n; ++k) {
            const bool edge = k < margin || k + margin >= n;
            (edge ? edge_acc : interior_acc) = std::max(edge ? edge_acc : interior_acc, s.acc[k].norm());
            (edge ? edge_gyr : interior_gyr) = std::max(edge ? edge_gyr : interior_gyr, s.gyr[k].norm());
        }
        // This recording jitters by about 1 cm per frame (|acc| swings 9-24 m/s^2 at the chest from one 50 ms
        // frame to the next); at the ends the spline sees that noise from one side only, so allow the ends up to
        // twice the interior's peak. A natural spline would pin acc to 0 there; finite differences of resampled
        // frames would spike at every frame.
        EXPECT_LT(edge_acc, 2 * interior_acc) << imu.mounts[i].placement.position;
        EXPECT_LT(edge_gyr, 2 * interior_gyr) << imu.mounts[i].placement.position;
    }
}
