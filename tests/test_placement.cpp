// Sensor placement sets: built-in sets, TOML sets, axis conventions.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <fstream>

#include "body/procedural_body.hpp"
#include "core/error.hpp"
#include "imu/placement.hpp"
#include "test_util.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::Matrix3d;
using Eigen::Vector3d;

TEST(Placement, BuiltinSetsHaveTheDatasetsPositions) {
    const auto names = [](const std::string& set) {
        std::vector<std::string> out;
        for (const SensorPlacement& p : builtin_placement_set(set).sensors) out.push_back(p.position);
        return out;
    };
    EXPECT_EQ(names("realworld"), (std::vector<std::string>{"chest", "left_forearm", "head", "left_shin", "left_thigh",
                                                            "left_upperarm", "waist"}));
    EXPECT_EQ(names("sisfall"), (std::vector<std::string>{"waist"}));
    EXPECT_EQ(names("umafall"), (std::vector<std::string>{"ankle", "waist", "chest", "wrist"}));
    EXPECT_EQ(names("hugadb").size(), 6u);
    EXPECT_THROW(builtin_placement_set("pamap2"), Error);
    EXPECT_THROW(parse_sensor_sets("sisfall,umafall"), Error);  // waist twice
}

TEST(Placement, MountedAxesAreRightHandedAndFollowTheWords) {
    const ProceduralBody body(paper_bodies()[2]);
    for (const std::string& set : builtin_placement_set_names())
        for (const SensorPlacement& p : builtin_placement_set(set).sensors) {
            const SensorMount m = mount_sensor(body, p);
            EXPECT_LT((m.rest_from_sensor.transpose() * m.rest_from_sensor - Matrix3d::Identity()).norm(), 1e-12)
                << p.position;
            EXPECT_NEAR(m.rest_from_sensor.determinant(), 1.0, 1e-12) << p.position;
        }
    // HuGaDB left thigh: x down the leg, z out of the front of the thigh, so y = z x x points to the left.
    const SensorMount thigh = mount_sensor(body, builtin_placement_set("hugadb").sensors[4]);
    EXPECT_EQ(thigh.placement.position, "left_thigh");
    EXPECT_LT((thigh.rest_from_sensor.col(0) - Vector3d(0, -1, 0)).norm(), 1e-12);
    EXPECT_LT((thigh.rest_from_sensor.col(2) - Vector3d(0, 0, 1)).norm(), 1e-12);
    EXPECT_LT((thigh.rest_from_sensor.col(1) - Vector3d(1, 0, 0)).norm(), 1e-12);
    // The sensor sits on the skin in front of the thigh, half-depth of the frustum ahead of the bone.
    EXPECT_GT(thigh.anchor.rest_position.z(), 0.05);
}

TEST(Placement, ReadsACustomTomlSet) {
    const std::string dir = test::scratch_dir("placement_toml");
    const std::string path = dir + "/mine.toml";
    std::ofstream(path)
        << "name = \"mine\"\n[[sensor]]\nposition = \"right_wrist\"\nsegment = \"right_elbow\"\nalong = 0.9\n"
           "around = -90\nx = \"distal\"\nz = \"out\"\nnote = \"watch\"\n";
    const PlacementSet set = read_placement_toml(path);
    ASSERT_EQ(set.sensors.size(), 1u);
    EXPECT_EQ(set.name, "mine");
    EXPECT_EQ(set.sensors[0].segment, right_elbow);
    EXPECT_DOUBLE_EQ(set.sensors[0].around_deg, -90);
    const ProceduralBody body(paper_bodies()[0]);
    const SensorMount m = mount_sensor(body, set.sensors[0]);
    EXPECT_LT((m.rest_from_sensor.col(2) - Vector3d(-1, 0, 0)).norm(), 1e-12);  // out of the right forearm's side
    const auto bad = [&](const std::string& body_text) {
        std::ofstream(path) << body_text;
        EXPECT_THROW(read_placement_toml(path), Error) << body_text;
    };
    bad("[[sensor]]\nposition = \"a\"\nsegment = \"elbow\"\nx = \"up\"\ny = \"out\"\n");  // not a joint name
    bad("[[sensor]]\nposition = \"a\"\nsegment = \"neck\"\nx = \"up\"\n");                // one axis
    bad("[[sensor]]\nposition = \"a\"\nsegment = \"neck\"\nx = \"sky\"\ny = \"out\"\n");  // unknown word
    bad("name = \"x\"\n");                                                                // no sensors
    bad("[[sensor]\n");                                                                   // not TOML
    // A float where an integer belongs is refused, not converted: 4.9e47 into an integer is undefined
    // behaviour (UBSan, fuzz/fuzz_sensor_toml).
    try {
        parse_placement_toml(
            "[[sensor]]\nposition = \"a\"\nsegment = \"neck\"\nvertex = 4.9e47\nx = \"up\"\ny = \"out\"\n", "v.toml");
        ADD_FAILURE() << "a float vertex was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("vertex: expected an integer"), std::string::npos) << e.what();
    }
    bad("[[sensor]]\nposition = \"a\"\nsegment = \"neck\"\nx = \"up\"\ny = \"out\"\naroud = -90\n");  // misspelt key
    bad("[[sensor]]\nposition = \"a\"\nsegment = \"neck\"\nx = \"up\"\ny = \"out\"\nalong = \"far\"\n");  // not a
                                                                                                          // number
    bad("[[sensor]]\nsegment = \"neck\"\nx = \"up\"\ny = \"out\"\n");                                     // no position
}
