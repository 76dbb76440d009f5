#include "report/pose_strip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/error.hpp"
#include "motion/skeleton.hpp"
#include "motion/support_ground.hpp"

namespace t2imu {

namespace {

constexpr double kCmPerM = 100;

std::string fixed(double v, int decimals = 1) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

const char* side_colour(int joint) {
    const char* name = smpl22::kJointNames[static_cast<size_t>(joint)];
    if (std::strncmp(name, "left_", 5) == 0) return "#3b75af";
    if (std::strncmp(name, "right_", 6) == 0) return "#e08a2c";
    return "#555";
}

// The ground (m) under the lowest foot joint at `frame`: the floor, or the tread or step the motion stands on.
double ground_under_feet(const JointSequence& joints, const SupportGround* ground, int frame) {
    if (ground == nullptr) return 0.0;
    int lowest = smpl22::kFootLeft[0];
    for (int j : {smpl22::kFootLeft[0], smpl22::kFootLeft[1], smpl22::kFootRight[0], smpl22::kFootRight[1]})
        if (joints.at(frame, j).y() < joints.at(frame, lowest).y()) lowest = j;
    return ground->height_at(joints.at(frame, lowest), frame);
}

// One pose in panel `panel`, drawn on the ground `ground_m` under its feet: the ground line, the 21 bones, the
// time label, and the ground's height above the floor where it is raised.
std::string pose_panel(const JointSequence& joints, int frame, int panel, double ground_m) {
    const double left = panel * kPanelWidthCm, centre_z = joints.at(frame, smpl22::pelvis).z();
    const auto x = [&](int j) {
        return fixed(left + kPanelWidthCm / 2 + kCmPerM * (joints.at(frame, j).z() - centre_z));
    };
    const auto y = [&](int j) { return fixed(kHeadroomCm - kCmPerM * (joints.at(frame, j).y() - ground_m)); };
    std::string out = "<line x1=\"" + fixed(left + 10) + "\" y1=\"" + fixed(kHeadroomCm) + "\" x2=\"" +
                      fixed(left + kPanelWidthCm - 10) + "\" y2=\"" + fixed(kHeadroomCm) + "\" stroke=\"#ccc\"/>\n";
    for (int j = 1; j < smpl22::kNumJoints; ++j) {
        const int p = smpl22::kParents[static_cast<size_t>(j)];
        out += "<line x1=\"" + x(p) + "\" y1=\"" + y(p) + "\" x2=\"" + x(j) + "\" y2=\"" + y(j) + "\" stroke=\"" +
               side_colour(j) + "\"/>\n";
    }
    std::string label = fixed(frame / joints.fps) + " s";
    if (ground_m != 0.0) label += std::string(", ground ") + (ground_m > 0 ? "+" : "") + fixed(ground_m, 2) + " m";
    out += "<text x=\"" + fixed(left + kPanelWidthCm / 2) + "\" y=\"" + fixed(kHeadroomCm + kBelowFloorCm - 6) + "\">" +
           label + "</text>\n";
    return out;
}

}  // namespace

std::vector<int> strip_frames(int num_frames, int poses) {
    const int n = std::min(num_frames, poses);
    if (n == 1) return {0};
    std::vector<int> frames;
    for (int k = 0; k < n; ++k)
        frames.push_back(static_cast<int>(std::lround(static_cast<double>(k) * (num_frames - 1) / (n - 1))));
    return frames;
}

std::string pose_strip_svg(const JointSequence& joints, int poses) {
    if (joints.num_joints != smpl22::kNumJoints || joints.num_frames < 1 || poses < 1)
        throw Error("pose strip", "motion", "SMPL-22 joints, at least one frame and one pose");
    const std::vector<int> frames = strip_frames(joints.num_frames, poses);
    const double width = kPanelWidthCm * static_cast<double>(frames.size()), height = kHeadroomCm + kBelowFloorCm;
    std::string out =
        "<svg class=\"pose-strip\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + fixed(width) + " " +
        fixed(height) + "\" width=\"" + fixed(width * kPoseStripPixelsPerCm) + "\" height=\"" +
        fixed(height * kPoseStripPixelsPerCm) +
        "\" stroke-width=\"4\" stroke-linecap=\"round\" font-size=\"18\" text-anchor=\"middle\" fill=\"#555\">\n";
    std::optional<SupportGround> ground;  // needs three frames to see a foot stand still
    if (joints.num_frames >= 3) ground.emplace(joints);
    for (size_t k = 0; k < frames.size(); ++k)
        out += pose_panel(joints, frames[k], static_cast<int>(k),
                          ground_under_feet(joints, ground ? &*ground : nullptr, frames[k]));
    return out + "</svg>";
}

}  // namespace t2imu
