// Where virtual sensors sit on a body and how their axes lie: the placement sets of the real data sets we
// compare with, and custom sets from TOML.
//
// A placement names a segment (by its proximal joint, segments.hpp), a height along it (0 = proximal joint,
// 1 = distal joint), an angle around it (degrees; 0 = front, +90 = the body's left, see procedural_body.hpp)
// and two of the sensor's axes in words; the third completes a right-handed frame. Axis words:
//   up, down, left, right, front, back   rest body directions (standing, facing +Z, left = +X)
//   out, in                              the skin's outward / inward normal at the sensor
//   distal, proximal                     along the segment, away from / towards the trunk
// The first named axis is taken exactly, the second is made perpendicular to it.
//
// Built-in sets and their sources (each sensor's `note` says what is documented and what is estimated):
//   realworld  RealWorld HAR (Sztyler & Stuckenschmidt 2016): smartphones (Android axes: x right across the
//              screen, y up along it, z out of the screen) upright with the screen facing out, and a watch on
//              the forearm. The release does not give the side of the limb sensors: placed on the left.
//   sisfall    SisFall: one board at the waist on the belt, front. Axes not documented: y points down and z
//              forwards, estimated from the data's mean gravity direction while walking (-y: 0.98 of g).
//   umafall    UMAFall: SensorTags at ankle, waist, chest, wrist; side not given (right ankle, left wrist
//              assumed). x points up along the body, estimated from the mean gravity while walking (ankle,
//              chest, waist: +x 0.97-1.00 of g); z out of the skin assumed (a tag lies flat on the skin).
//   hugadb     HuGaDB: left/right foot, shin, thigh, on the front of each segment (top of the foot). x points
//              distally, estimated from the mean gravity while walking (-x 0.94-1.00 of g on thighs and
//              shins); z out of the skin assumed.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "body/body_model.hpp"

namespace t2imu {

struct SensorPlacement {
    std::string position;  // the canonical position name the output uses: "left_shin", "waist"
    int segment = 0;       // proximal joint of the segment
    double along = 0.5;
    double around_deg = 0;
    std::string axis[3];  // words for x, y, z; exactly one is empty
    int vertex = -1;      // SMPL bodies only: this skin vertex instead of along/around
    std::string note;     // where the mounting comes from
};

struct PlacementSet {
    std::string name;
    std::vector<SensorPlacement> sensors;
};

// The data sets' placement sets (dataset_profile.hpp), by the data set's name; Error naming `option` for another name.
std::vector<std::string> builtin_placement_set_names();
PlacementSet builtin_placement_set(const std::string& name, const std::string& option = "--sensors");
// Throws Error naming `file` and the position unless exactly two axes are given, each one of the words above.
void check_placement(const SensorPlacement& placement, const std::string& file);
// A custom set: `name = "..."` and [[sensor]] tables with position, segment (a joint name), along, around
// (degrees), two of x/y/z, optional vertex and note. Errors name the file and the field.
PlacementSet read_placement_toml(const std::string& path);
PlacementSet parse_placement_toml(const std::string& text, const std::string& source);  // the same on a file's text
// "--sensors realworld,hugadb" or a .toml path (or a mix); positions must be distinct across the sets.
std::vector<SensorPlacement> parse_sensor_sets(const std::string& text);

// A placement resolved on one body: its anchor on the skin and the sensor's axes in rest body coordinates
// (columns x, y, z), optionally turned by a mounting error (in the sensor frame) and tilted (realism.hpp: the
// skin normal turned down by tilt_down_deg about the skin's horizontal tangent; none where the normal is vertical).
struct SensorMount {
    SensorPlacement placement;
    BodyAnchor anchor;
    Eigen::Matrix3d rest_from_sensor;
    Eigen::Vector3d skin_normal = Eigen::Vector3d::UnitZ();  // outward, rest body coordinates
    // The skin's horizontal tangent (up x normal, unit, rest body coordinates): the direction a belt or a strap
    // around the segment runs, and the axis of the tilt; zero where the skin faces up or down.
    Eigen::Vector3d horizontal_tangent = Eigen::Vector3d::Zero();
    Eigen::Vector3d horizontal_tangent_in_sensor() const { return rest_from_sensor.transpose() * horizontal_tangent; }
};
SensorMount mount_sensor(const BodyModel& body, const SensorPlacement& placement, double tilt_down_deg = 0);

}  // namespace t2imu
