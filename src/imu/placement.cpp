#include "imu/placement.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/toml_section.hpp"
#include "imu/dataset_profile.hpp"

namespace t2imu {

using namespace smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

int joint_index(const std::string& name, const std::string& file) {
    for (int j = 0; j < kNumJoints; ++j)
        if (name == kJointNames[static_cast<size_t>(j)]) return j;
    throw Error(file, "segment", "an SMPL-22 joint name (pelvis, left_hip, ..., right_wrist)", name);
}

const std::set<std::string> kAxisWords = {"up",   "down", "left", "right",  "front",
                                          "back", "out",  "in",   "distal", "proximal"};

}  // namespace

void check_placement(const SensorPlacement& p, const std::string& file) {
    int given = 0;
    for (const std::string& a : p.axis) {
        if (a.empty()) continue;
        ++given;
        if (!kAxisWords.count(a))
            throw Error(file, p.position + " axis", "up|down|left|right|front|back|out|in|distal|proximal", a);
    }
    if (given != 2) throw Error(file, p.position + " axes", "exactly two of x, y, z", std::to_string(given));
}

namespace {

Vector3d axis_direction(const std::string& word, const Vector3d& normal, const Vector3d& distal) {
    if (word == "up") return Vector3d::UnitY();
    if (word == "down") return -Vector3d::UnitY();
    if (word == "left") return Vector3d::UnitX();
    if (word == "right") return -Vector3d::UnitX();
    if (word == "front") return Vector3d::UnitZ();
    if (word == "back") return -Vector3d::UnitZ();
    if (word == "out") return normal;
    if (word == "in") return -normal;
    if (word == "distal") return distal;
    return -distal;  // proximal
}

}  // namespace

std::vector<std::string> builtin_placement_set_names() {
    std::vector<std::string> names;
    for (const DatasetProfile& p : dataset_profiles()) names.push_back(p.name);
    return names;
}

PlacementSet builtin_placement_set(const std::string& name, const std::string& option) {
    const DatasetProfile* profile = find_dataset_profile(name);
    if (!profile) throw Error(option, "set", dataset_profile_names() + " or a .toml file", name);
    PlacementSet set{name, profile->placements};
    for (const SensorPlacement& p : set.sensors) check_placement(p, name);
    return set;
}

PlacementSet read_placement_toml(const std::string& path) { return parse_placement_toml(read_file_text(path), path); }

PlacementSet parse_placement_toml(const std::string& text, const std::string& path) {
    // Strict: a misspelt key ("aroud") or a wrong type (along = "far") is refused by name, not left at its default.
    const toml::table doc = parse_toml_text(text, path);
    TomlSection top(doc, path, "");
    PlacementSet set;
    set.name = "custom";
    top.read("name", set.name);
    std::vector<TomlSection> sensors = top.array_of_tables("sensor");
    top.refuse_unknown_keys();
    if (sensors.empty()) throw Error(path, "sensor", "at least one [[sensor]] table");
    for (TomlSection& t : sensors) {
        SensorPlacement p;
        std::string segment;
        int64_t vertex = -1;
        p.note = "custom placement from " + path;
        t.require("position", p.position);
        t.require("segment", segment);
        t.read("along", p.along);
        t.read("around", p.around_deg);
        t.read("vertex", vertex);
        t.read("note", p.note);
        const char* keys[3] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a) t.read(keys[a], p.axis[a]);
        t.refuse_unknown_keys();
        if (p.position.empty()) throw Error(path, "position", "a position name in every [[sensor]]");
        p.segment = joint_index(segment, path);
        if (vertex < -1 || vertex > std::numeric_limits<int>::max())
            throw Error(path, p.position + " vertex", "a vertex index (0 or more)", std::to_string(vertex));
        p.vertex = static_cast<int>(vertex);
        if (!std::isfinite(p.along) || p.along < -0.5 || p.along > 2.0)
            throw Error(path, p.position + " along", "-0.5 to 2", std::to_string(p.along));
        if (!std::isfinite(p.around_deg)) throw Error(path, p.position + " around", "degrees");
        check_placement(p, path);
        set.sensors.push_back(p);
    }
    return set;
}

std::vector<SensorPlacement> parse_sensor_sets(const std::string& text) {
    std::vector<SensorPlacement> out;
    std::set<std::string> seen;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const bool toml = item.size() > 5 && ends_with(item, ".toml");
        const PlacementSet set = toml ? read_placement_toml(item) : builtin_placement_set(item);
        for (const SensorPlacement& p : set.sensors) {
            if (!seen.insert(p.position).second)
                throw Error("--sensors", "position", "distinct positions across the sets", p.position + " twice");
            out.push_back(p);
        }
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

SensorMount mount_sensor(const BodyModel& body, const SensorPlacement& placement, double tilt_down_deg) {
    SensorMount m;
    m.placement = placement;
    SurfacePoint surface;
    if (placement.vertex >= 0) {
        if (body.spec().kind != BodySpec::Kind::smpl)
            throw Error("--sensors", placement.position + " vertex", "an SMPL body (--body smpl:FILE)");
        surface = body.vertex_point(placement.vertex);
    } else {
        surface = body.surface_point(placement.segment, placement.along, placement.around_deg * M_PI / 180);
    }
    m.anchor = body.anchor(placement.segment, surface);
    m.skin_normal = surface.normal;
    const RestAxes axes = rest_axes(body.rest_joints());
    const Vector3d distal = axes.long_axis[static_cast<size_t>(placement.segment)];
    int first = -1, second = -1;
    for (int a = 0; a < 3; ++a)
        if (!placement.axis[a].empty()) (first < 0 ? first : second) = a;
    const Vector3d u = axis_direction(placement.axis[first], surface.normal, distal).normalized();
    Vector3d v = axis_direction(placement.axis[second], surface.normal, distal);
    v = (v - v.dot(u) * u);
    if (v.norm() < 1e-6)
        throw Error("--sensors", placement.position + " axes", "two axes that are not parallel on this body");
    v.normalize();
    Matrix3d r;
    r.col(first) = u;
    r.col(second) = v;
    const int third = 3 - first - second;
    // Right-handed: x = y x z, y = z x x, z = x x y.
    r.col(third) = r.col((third + 1) % 3).cross(r.col((third + 2) % 3));
    m.rest_from_sensor = r;
    // Tilt: about up x normal, which turns the normal towards -up (rest frame: Y up).
    const Vector3d tangent = Vector3d::UnitY().cross(surface.normal);
    if (tangent.norm() > 0.1) m.horizontal_tangent = tangent.normalized();
    if (tilt_down_deg != 0 && m.horizontal_tangent.squaredNorm() > 0)
        m.rest_from_sensor =
            Eigen::AngleAxisd(tilt_down_deg * M_PI / 180, m.horizontal_tangent).toRotationMatrix() * m.rest_from_sensor;
    return m;
}

}  // namespace t2imu
