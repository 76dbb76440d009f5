#include "report_fixture.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/npy.hpp"
#include "imu/synth_folder.hpp"
#include "motion/bvh_export.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

namespace t2imu::test {

namespace {

Eigen::Matrix3d rot_x(double degrees) {
    return Eigen::AngleAxisd(degrees * test::kPi / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

void write_job(const std::string& dir, const nlohmann::json& marker) {
    write_file_atomic(dir + "/jobs/" + marker["job"].get<std::string>() + ".json", marker.dump(1) + "\n");
}

void write_motion(const std::string& dir, const std::string& job) {
    const JointSequence walk = fixture_walk(40);
    write_npy(dir + "/" + job_joints_file(job), joint_sequence_to_array(walk));
    write_bvh(dir + "/" + job_bvh_file(job), smpl22_to_bvh(walk));
}

nlohmann::json quality(double foot_skate) {
    return {{"foot_skate_m_s", foot_skate}, {"penetration_m", 0.0}, {"hover_m", 0.01},
            {"max_speed_m_s", 4.0},         {"max_acc_m_s2", 40.0}, {"pelvis_acc_m_s2", 8.0}};
}

}  // namespace

JointSequence fixture_walk(int frames, double stride_hz) {
    using namespace smpl22;
    JointSequence s(frames, kNumJoints, kFps);
    double lowest = 0;
    for (int f = 0; f < frames; ++f) {
        const double swing = std::sin(2 * test::kPi * stride_hz * f / kFps);  // +1: left leg forward
        std::array<Eigen::Matrix3d, kNumJoints> local;
        local.fill(Eigen::Matrix3d::Identity());
        local[left_hip] = rot_x(-25 * swing);  // a negative angle about X swings a hanging bone forward (+Z)
        local[right_hip] = rot_x(25 * swing);
        local[left_knee] = rot_x(15 * (1 + swing));
        local[right_knee] = rot_x(15 * (1 - swing));
        local[left_shoulder] = rot_x(20 * swing);
        local[right_shoulder] = rot_x(-20 * swing);
        std::array<Eigen::Matrix3d, kNumJoints> global;
        global[0] = local[0];
        s.at(f, pelvis) = Eigen::Vector3d(0, 0, static_cast<double>(f) / kFps);  // 1 m/s along +Z
        for (int j = 1; j < kNumJoints; ++j) {
            const int p = kParents[static_cast<size_t>(j)];
            global[static_cast<size_t>(j)] = global[static_cast<size_t>(p)] * local[static_cast<size_t>(j)];
            s.at(f, j) = s.at(f, p) + global[static_cast<size_t>(p)] * kTargetOffsets[static_cast<size_t>(j)];
            lowest = std::min(lowest, s.at(f, j).y());
        }
    }
    for (Eigen::Vector3d& p : s.positions) p.y() -= lowest;
    return s;
}

ImuRecording sine_recording(const std::string& path, const std::string& activity, const std::string& position,
                            double amplitude, double hz, double rate_hz, double seconds) {
    ImuRecording r;
    r.path = path;
    r.dataset = "fixture";
    r.subject = "s1";
    r.activity = activity;
    r.position = position;
    r.rate_hz = rate_hz;
    for (int i = 0; i < static_cast<int>(std::lround(seconds * rate_hz)); ++i) {
        r.t.push_back(i / rate_hz);
        r.samples.push_back({0, 9.81 + amplitude * std::sin(2 * test::kPi * hz * r.t.back()), 0, 0, 0, 0});
    }
    return r;
}

namespace {

// A job marker's recordings list (imu/synth_folder.hpp's schema): 4 s at 64 Hz each.
nlohmann::json recordings(const std::string& job,
                          const std::vector<std::pair<std::string, std::string>>& body_positions) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [body, position] : body_positions)
        list.push_back({{"path", "recordings/" + job + "/" + body + "/" + position + ".csv"},
                        {"body", body},
                        {"position", position},
                        {"n_samples", 256}});
    return list;
}

}  // namespace

void write_synth_fixture(const std::string& dir) {
    write_job(dir, {{"job", "j00000"},
                    {"index", 0},
                    {"prompt", "a person walks forward briskly"},
                    {"activity", "walking"},
                    {"seed", 10},
                    {"attempts", {{{"seed", 10}, {"failures", nlohmann::json::array()}}}},
                    {"quality", quality(0.2)},
                    {"kept", true},
                    {"activity_check", {{"shown", "walking"}, {"agreement", 0.83}, {"passed", true}}},
                    {"recordings", recordings("j00000", {{"b0", "waist"}, {"b1", "waist"}, {"b0", "chest"}})}});
    write_job(dir, {{"job", "j00001"},
                    {"index", 1},
                    {"prompt", "someone jogs in place"},
                    {"activity", "running"},
                    {"seed", 1011},
                    {"attempts",
                     {{{"seed", 11}, {"failures", {"foot_skate_m_s"}}}, {{"seed", 1011}, {"failures", {"activity"}}}}},
                    {"quality", quality(0.4)},
                    {"kept", true},
                    {"activity_check", {{"shown", "walking"}, {"agreement", 0.4}, {"passed", false}}},
                    {"recordings", recordings("j00001", {{"b0", "waist"}})}});
    write_job(dir, {{"job", "j00002"},
                    {"index", 2},
                    {"prompt", "a person strolls"},
                    {"activity", "walking"},
                    {"seed", 12},
                    {"attempts", {{{"seed", 12}, {"failures", {"hover_m"}}}}},
                    {"quality", quality(0.1)},
                    {"kept", false},
                    {"recordings", nlohmann::json::array()}});
    write_motion(dir, "j00000");
    write_motion(dir, "j00001");
    write_imu_dataset(dir, {sine_recording("recordings/j00000/b0/waist.csv", "walking", "waist", 1, 2),
                            sine_recording("recordings/j00000/b1/waist.csv", "walking", "waist", 3, 2),
                            sine_recording("recordings/j00000/b0/chest.csv", "walking", "chest", 1, 2),
                            sine_recording("recordings/j00001/b0/waist.csv", "running", "waist", 4, 3)});
    write_file_atomic(
        dir + "/synth_report.json",
        R"({"jobs":3,"jobs_done":3,"motions_kept":2,"motions_dropped":1,"jobs_regenerated":1,"recordings":4,"failed_attempts_by_score":{},"quality_median":{},)"
        R"("per_activity":{"running":{"kept":1,"kept_below_activity_agreement":1,"dropped":0,"shown":{"walking":1}},)"
        R"("walking":{"kept":1,"kept_below_activity_agreement":0,"dropped":1,"shown":{"walking":1}}},)"
        R"("this_run":{"jobs_run":3,"total_s":2.5,"motion_generation_s":2.0,"bodies_imu_write_s":0.4,"device":"cpu"}})");
}

void write_real_fixture(const std::string& dir) {
    write_imu_dataset(dir, {sine_recording("s1/walking_waist.csv", "walking", "waist", 2, 1.75),
                            sine_recording("s1/walking_chest.csv", "walking", "chest", 2, 1.75),
                            sine_recording("s1/applauding_waist.csv", "applauding", "waist", 5, 4)});
}

}  // namespace t2imu::test
