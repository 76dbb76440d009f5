#include "imu/dataset_profile.hpp"

#include <cmath>

#include "core/error.hpp"
#include "imu/realism.hpp"

namespace t2imu {

using namespace smpl22;

namespace {

constexpr double kG = 9.80665, kDeg = M_PI / 180;

SensorPlacement place(const char* position, int segment, double along, double around, const char* x, const char* y,
                      const char* z, const char* note) {
    SensorPlacement p;
    p.position = position, p.segment = segment, p.along = along, p.around_deg = around, p.note = note;
    p.axis[0] = x, p.axis[1] = y, p.axis[2] = z;
    return p;
}

SensorNoiseModel named(SensorNoiseModel m, const std::string& name) {
    m.name = name;
    return m;
}

const char* kPhone = "smartphone upright, screen out (Android axes); placement per RealWorld's position name";
const char* kEstimated = "up axis estimated from the real data's mean gravity while walking; z out of the skin assumed";

// RealWorld HAR (Sztyler & Stuckenschmidt 2016): smartphones upright, screen out (Android axes: x right across the
// screen, y up along it, z out of it) and a watch on the forearm; the release gives no side: the left. Its device is
// the smartphone chip; its tilt is not calibrated (no RealWorld data here): a phone in a pocket turns by about 8 deg.
DatasetProfile realworld() {
    DatasetProfile p;
    p.name = "realworld";
    p.about = "RealWorld HAR: smartphones at seven positions and a watch, 50 Hz";
    p.placements = {
        place("chest", spine3, 0.3, 0, "", "up", "out", kPhone),
        place("left_forearm", left_elbow, 0.85, 90, "distal", "", "out",
              "watch on the back of the wrist; side not given by the release"),
        place("head", neck, 1.25, 90, "", "up", "out",
              "strapped to the side of the head; side not given by the release"),
        place("left_shin", left_knee, 0.4, 90, "", "proximal", "out", kPhone),
        place("left_thigh", left_hip, 0.4, 90, "", "proximal", "out", kPhone),
        place("left_upperarm", left_shoulder, 0.45, 90, "", "proximal", "out", kPhone),
        place("waist", pelvis, 0.3, 0, "", "up", "out", kPhone),
    };
    p.sensor = named(smartphone_sensor(), p.name);
    p.tilt_spread_deg = 8;
    return p;  // climbingup/down become stairs_up/down in its importer; the other names are canonical
}

// SisFall: one board on the belt at the front of the waist: ADXL345 (+-16 g, 13 bit: 3.9 mg/LSB; about 300
// ug/sqrt(Hz)) and ITG-3200 (0.038 deg/s/sqrt(Hz), +-2000 deg/s; its zero-rate offset left uncalibrated, sd taken as
// 3 deg/s). Axes not documented: y down, z forwards, from the data's mean gravity while walking. Its tilt: the real
// waist's mean tilt and its spread over recordings beyond the synthetic one (docs/realism.md, "The levers").
// Its "jogging" trials are slow runs; stairs_up_down goes up and down in one trial; jump_reach is mostly standing.
DatasetProfile sisfall() {
    DatasetProfile p;
    p.name = "sisfall";
    p.about = "SisFall: one board (ADXL345, ITG-3200) on the belt at the waist, 200 Hz";
    p.placements = {
        place("waist", pelvis, 0.3, 0, "", "down", "front", "belt, front; -y up estimated from mean gravity (0.98 g)")};
    SensorNoiseModel m = smartphone_sensor();
    m.acc_noise_density = 300e-6 * kG;
    m.gyr_noise_density = 0.038 * kDeg;
    m.gyr_bias_sd = 3 * kDeg;
    m.acc_range = 16 * kG;
    m.bits = 13;
    p.sensor = named(m, p.name);
    p.tilt_mean_deg = 7.5, p.tilt_spread_deg = 10;
    p.class_map = {{"jogging", "running"}, {"stairs_up_down", "stairs"}, {"jump_reach", ""}};
    return p;
}

// UMAFall: SensorTags (MPU-9250: the smartphone chip with acc 300 ug/sqrt(Hz), gyro 0.01 deg/s/sqrt(Hz)) at ankle,
// waist, chest and wrist; side not given (right ankle, left wrist assumed); x up along the body from the data's mean
// gravity while walking. Its tilt has no common direction but a spread over recordings (docs/realism.md).
// Its "jumping" is UMAFall's Hopping, kept as jumping.
DatasetProfile umafall() {
    DatasetProfile p;
    p.name = "umafall";
    p.about = "UMAFall: SensorTags (MPU-9250) at ankle, waist, chest and wrist, 20 Hz";
    p.placements = {
        place("ankle", right_knee, 0.9, -90, "proximal", "", "out", kEstimated),
        place("waist", pelvis, 0.3, 0, "up", "", "out", kEstimated),
        place("chest", spine3, 0.4, 0, "up", "", "out", kEstimated),
        place("wrist", left_elbow, 0.9, 90, "distal", "", "out",
              "x along the forearm and z out of the skin assumed: the data's mean gravity is inconsistent across "
              "subjects"),
    };
    SensorNoiseModel m = smartphone_sensor();
    m.acc_noise_density = 300e-6 * kG;
    m.gyr_noise_density = 0.01 * kDeg;
    p.sensor = named(m, p.name);
    p.tilt_spread_deg = 13;
    p.class_map = {{"jogging", "running"}};
    return p;
}

// HuGaDB: straps on the front of each foot (top), shin and thigh, both legs; x distal from the data's mean gravity
// while walking. Its device: the smartphone chip at +-2 g (clips fast walking at the feet). Its tilt is not
// calibrated (the shared copy has no waist sensor): a strap on a leg turns less than a belt clip, 5 deg.
DatasetProfile hugadb() {
    DatasetProfile p;
    p.name = "hugadb";
    p.about = "HuGaDB: straps on both feet, shins and thighs, about 59 Hz";
    const int segments[3][2] = {{left_ankle, right_ankle}, {left_knee, right_knee}, {left_hip, right_hip}};
    const char* positions[3][2] = {
        {"left_foot", "right_foot"}, {"left_shin", "right_shin"}, {"left_thigh", "right_thigh"}};
    for (int k = 0; k < 3; ++k)
        for (int side = 0; side < 2; ++side)
            p.placements.push_back(place(positions[k][side], segments[k][side], 0.5, 0, "distal", "", "out",
                                         "front of the segment (top of the foot); -x up estimated from mean gravity"));
    SensorNoiseModel m = smartphone_sensor();
    m.acc_range = 2 * kG;
    p.sensor = named(m, p.name);
    p.tilt_spread_deg = 5;
    return p;
}

struct Registry {
    std::deque<DatasetProfile> profiles = {realworld(), sisfall(), umafall(), hugadb()};
    const size_t builtin = profiles.size();  // the first ones; those after were added
};

Registry& registry() {
    static Registry r;
    return r;
}

}  // namespace

const std::deque<DatasetProfile>& dataset_profiles() { return registry().profiles; }

const DatasetProfile* find_dataset_profile(const std::string& name) {
    for (const DatasetProfile& p : registry().profiles)
        if (p.name == name) return &p;
    return nullptr;
}

std::string dataset_profile_names() {
    std::string names;
    for (const DatasetProfile& p : registry().profiles) names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

void check_dataset_profile(const DatasetProfile& p) {
    const std::string source = "dataset profile " + (p.name.empty() ? std::string("(unnamed)") : p.name);
    if (p.name.empty() || p.name == "none" || p.name == "smartphone" || p.name == "t2imu" ||
        p.name.find_first_of("+-,/ ") != std::string::npos)
        throw Error(source, "name", "a name of its own, without + - , / or blanks", p.name);
    if (p.about.empty()) throw Error(source, "about", "a line saying what was recorded with what");
    if (p.placements.empty()) throw Error(source, "placements", "at least one sensor placement");
    for (const SensorPlacement& s : p.placements) check_placement(s, source);
    if (p.sensor.name != p.name)
        throw Error(source, "sensor", "a sensor model named after the data set", p.sensor.name);
    RealismModel tilt;
    tilt.tilt = {p.tilt_mean_deg, p.tilt_spread_deg};
    tilt.validate(source);
}

void add_dataset_profile(DatasetProfile profile) {
    check_dataset_profile(profile);
    if (find_dataset_profile(profile.name))
        throw Error("dataset profile " + profile.name, "name", "a name no other profile has", profile.name);
    if (!profile.importer) throw Error("dataset profile " + profile.name, "importer", "a reader of its release format");
    registry().profiles.push_back(std::move(profile));
}

void remove_dataset_profile(const std::string& name) {
    std::deque<DatasetProfile>& profiles = registry().profiles;
    for (auto it = profiles.begin() + static_cast<std::ptrdiff_t>(registry().builtin); it != profiles.end(); ++it)
        if (it->name == name) {
            profiles.erase(it);
            return;
        }
}

}  // namespace t2imu
