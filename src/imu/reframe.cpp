#include "imu/reframe.hpp"

#include "core/error.hpp"

namespace t2imu {

Eigen::Matrix3d reframe_rotation(const BodyModel& body, const SensorPlacement& from, const SensorPlacement& to) {
    // rest_from_sensor maps sensor axes into the rest body frame; the inverse of an orthonormal frame is its
    // transpose.
    return mount_sensor(body, to).rest_from_sensor.transpose() * mount_sensor(body, from).rest_from_sensor;
}

void reframe_recording(const Eigen::Matrix3d& to_from, ImuRecording& recording) {
    for (std::array<double, 6>& s : recording.samples)
        for (int v = 0; v < 2; ++v) {  // acc xyz, then gyr xyz
            double* xyz = s.data() + 3 * v;
            const Eigen::Vector3d turned = to_from * Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
            for (int c = 0; c < 3; ++c) xyz[c] = turned[c];
        }
}

const SensorPlacement& placement_at(const PlacementSet& set, const std::string& position, const std::string& option) {
    std::string positions;
    for (const SensorPlacement& p : set.sensors) {
        if (p.position == position) return p;
        positions += (positions.empty() ? "" : ", ") + p.position;
    }
    throw Error(option, position, "a position the set " + set.name + " places (" + positions + ")");
}

}  // namespace t2imu
