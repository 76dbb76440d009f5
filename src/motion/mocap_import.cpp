#include "motion/mocap_import.hpp"

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "motion/asf_amc.hpp"
#include "motion/bvh.hpp"
#include "motion/resample.hpp"
#include "motion/skeleton_map.hpp"

namespace t2imu {

namespace {

bool root_rotation_is_zero(const BvhMotion& m, int frame) {
    const BvhJoint& root = m.joints[0];
    const double* v = m.frame(frame);
    for (size_t c = 0; c < root.channels.size(); ++c)
        if (root.channels[c] >= BvhChannel::x_rotation && v[root.first_channel + static_cast<int>(c)] != 0.0)
            return false;
    return true;
}

// Resamples local poses to options.fps and places the 22 SMPL joints (metres) by the skeleton map.
JointSequence smpl_joints_from_poses(const BvhMotion& structure, const SkeletonMap& map, double metres_per_unit,
                                     const std::vector<BvhPose>& poses, double frame_time, double fps) {
    std::vector<int> from(22), to(22);
    for (size_t j = 0; j < 22; ++j) {
        from[j] = structure.find(map.joints[j].from);
        to[j] = map.joints[j].to.empty() ? -1 : structure.find(map.joints[j].to);
    }
    if (fps == 0) fps = capture_fps_for(1.0 / frame_time);
    const std::vector<BvhPose> resampled = resample_poses(poses, frame_time, fps);
    JointSequence out(static_cast<int>(resampled.size()), 22, fps);
    for (int f = 0; f < out.num_frames; ++f) {
        const std::vector<Eigen::Vector3d> world = bvh_forward_kinematics(structure, resampled[static_cast<size_t>(f)]);
        for (size_t j = 0; j < 22; ++j) {
            Eigen::Vector3d p = world[static_cast<size_t>(from[j])];
            if (to[j] >= 0) p = (1 - map.joints[j].t) * p + map.joints[j].t * world[static_cast<size_t>(to[j])];
            out.at(f, static_cast<int>(j)) = p * metres_per_unit;
        }
    }
    return out;
}

std::vector<std::string> joint_names(const BvhMotion& m) {
    std::vector<std::string> names;
    for (const BvhJoint& j : m.joints) names.push_back(j.name);
    return names;
}

JointSequence import_bvh(const std::string& path, const ImportOptions& options) {
    const BvhMotion m = read_bvh(path);
    const SkeletonMap& map = find_skeleton_map(joint_names(m), path);
    const int first = map.zero_root_first_frame_is_tpose && m.num_frames > 1 && root_rotation_is_zero(m, 0) ? 1 : 0;
    std::vector<BvhPose> poses;
    for (int f = first; f < m.num_frames; ++f) poses.push_back(bvh_pose(m, f, map.positions));
    return smpl_joints_from_poses(m, map, map.metres_per_unit, poses, m.frame_time, options.fps);
}

// The ASF of an AMC clip: the .asf beside it whose name (without extension) is the longest prefix of the clip's
// name, as HDM05 names them (HDM_bd.asf for HDM_bd_walk_001_120.amc).
std::string find_asf_for(const std::string& amc) {
    namespace fs = std::filesystem;
    const fs::path p(amc);
    const std::string stem = p.stem().string();
    std::string best;
    for (const auto& e : fs::directory_iterator(p.has_parent_path() ? p.parent_path() : fs::path("."))) {
        if (e.path().extension() != ".asf" && e.path().extension() != ".ASF") continue;
        const std::string s = e.path().stem().string();
        if (stem.compare(0, s.size(), s) == 0 && s.size() > fs::path(best).stem().string().size())
            best = e.path().string();
    }
    if (best.empty())
        throw Error(amc, "--asf", "an .asf beside the clip whose name is a prefix of the clip's name, or --asf");
    return best;
}

JointSequence import_amc(const std::string& path, const ImportOptions& options) {
    const AsfSkeleton asf = read_asf(options.asf.empty() ? find_asf_for(path) : options.asf);
    const std::vector<BvhPose> poses = read_amc(path, asf);
    const SkeletonMap& map = find_skeleton_map(joint_names(asf.structure), path);
    return smpl_joints_from_poses(asf.structure, map, asf.metres_per_unit, poses, 1.0 / options.source_fps,
                                  options.fps);
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext.empty() ? ext : ext.substr(1);
}

// A Z-up source turned to Y up by a rotation of -90 degrees about X: (x, y, z) -> (x, z, -y).
JointSequence z_up_to_y_up(JointSequence s) {
    for (Eigen::Vector3d& p : s.positions) p = Eigen::Vector3d(p.x(), p.z(), -p.y());
    return s;
}

JointSequence import_motion_as_captured(const std::string& path, const ImportOptions& options) {
    const std::string format = options.format.empty() ? lower_extension(path) : options.format;
    if (format == "bvh") return import_bvh(path, options);
    if (format == "amc") return import_amc(path, options);
    if (format == "npy" && options.fps == 0)
        throw Error(path, "--fps", "the joints' frame rate (an .npy does not record it)", "0");
    if (format == "npy") return joint_sequence_from_array(read_npy(path), path, 22, 1, options.fps);
    throw Error(path, "format", "bvh, amc or npy (by extension, or --format)", format.empty() ? "none" : format);
}

}  // namespace

double capture_fps_for(double capture_fps) {
    if (!(capture_fps > 0 && std::isfinite(capture_fps)))
        throw Error("import", "capture rate", "a positive frame rate", std::to_string(capture_fps));
    // Rates are printed rounded (0.00833333 s for 1/120 s): a thousandth over a whole multiple still divides.
    return capture_fps / std::max(1.0, std::ceil(capture_fps / kMaxCaptureFps - 1e-3));
}

JointSequence import_motion(const std::string& path, const ImportOptions& options) {
    if (!(options.fps >= 0) || options.fps > 1000)
        throw Error(path, "--fps", "a frame rate in (0, 1000], or 0 for the capture rate");
    if (options.up != 'y' && options.up != 'z') throw Error(path, "--up", "y or z", std::string(1, options.up));
    JointSequence s = import_motion_as_captured(path, options);
    return options.up == 'z' ? z_up_to_y_up(std::move(s)) : s;
}

}  // namespace t2imu
