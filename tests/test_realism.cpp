// The realism model (imu/realism) through the whole bodies/IMU stage: off is the ideal sensor to the byte, a
// tempo of 1 is the identity, a static body reads gravity only whatever the attachment, the tilt and the tempo
// are the ones drawn, landings make the attachment ring; presets and TOML files are read strictly. And realism.cpp
// on its own: what every preset turns on, the draws' distributions, validation naming the key, the JSON form
// read back as a TOML file, .toml paths, and the lever table: spelled variants, the help, retired keys, and each key
// written in at most two files of src/.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>

#include "body/procedural_body.hpp"
#include "core/error.hpp"
#include "imu/realism.hpp"
#include "imu/virtual_imu.hpp"
#include "motion/skeleton.hpp"
#include "test_util.hpp"

using namespace t2imu;
using namespace t2imu::smpl22;
using Eigen::Vector3d;

namespace {

const BodySpec& average_man() { return paper_bodies()[2]; }

JointSequence standing(int frames = 60) {
    const ProceduralBody body(average_man());
    JointSequence s(frames, kNumJoints, 20);
    for (int f = 0; f < frames; ++f)
        for (int j = 0; j < kNumJoints; ++j) s.at(f, j) = body.rest_joints()[j];
    return s;
}

// The rest skeleton bouncing vertically with a sharp landing every 0.5 s: the body drops 15 cm and stops.
JointSequence hopping() {
    const ProceduralBody body(average_man());
    JointSequence s(121, kNumJoints, 20);
    for (int f = 0; f < s.num_frames; ++f) {
        const double phase = std::fmod(f / 20.0, 0.5) / 0.5;
        const double lift = phase < 0.5 ? 0.15 * std::sin(M_PI * phase * 2) : 0;
        for (int j = 0; j < kNumJoints; ++j) s.at(f, j) = body.rest_joints()[j] + Vector3d(0, lift, 0);
    }
    return s;
}

VirtualImuOptions with(const RealismModel& m) {
    VirtualImuOptions o;
    o.set_realism(m);
    o.seed = 7;
    return o;
}

double mean_y(const ImuSignals& s, size_t from) {
    double sum = 0;
    for (size_t k = from; k < s.acc.size(); ++k) sum += s.acc[k].y();
    return sum / static_cast<double>(s.acc.size() - from);
}

}  // namespace

TEST(Realism, OffAndTempoOneAreTheIdealSensorToTheByte) {
    const JointSequence motion = hopping();
    const std::vector<SensorPlacement> sensors = parse_sensor_sets("umafall");
    const BodyImu ideal = synthesize_body_imu(motion, average_man(), sensors, {});
    RealismModel off = realism_preset("none");
    off.name = "renamed";  // every lever off, whatever the name
    const BodyImu same = synthesize_body_imu(motion, average_man(), sensors, with(off));
    EXPECT_EQ(same.tempo, 1.0);
    for (size_t s = 0; s < sensors.size(); ++s)
        for (size_t k = 0; k < ideal.signals[s].acc.size(); ++k) {
            EXPECT_EQ(ideal.signals[s].acc[k], same.signals[s].acc[k]);
            EXPECT_EQ(ideal.signals[s].gyr[k], same.signals[s].gyr[k]);
        }
}

TEST(Realism, StaticBodyOnSoftTissueReadsGravityOnly) {
    RealismModel m = realism_preset("sisfall");
    m.sensor = "none";
    m.tissue = {10, 0.5};
    m.strap = {6, 0.25};
    m.vibration.gain = 0.5;  // scaled by the motion's level: none here
    const BodyImu imu = synthesize_body_imu(standing(), average_man(), parse_sensor_sets("realworld"), with(m));
    for (const ImuSignals& s : imu.signals)
        for (size_t k = 0; k < s.acc.size(); ++k) {
            EXPECT_NEAR(s.acc[k].norm(), kGravity, 1e-9);
            EXPECT_LT(s.gyr[k].norm(), 1e-9);
        }
}

TEST(Realism, TiltTurnsTheBeltSensorsOutwardAxisDown) {
    RealismModel m;
    m.tilt.mean_deg = 15;
    const BodyImu imu = synthesize_body_imu(standing(), average_man(), parse_sensor_sets("sisfall"), with(m));
    ASSERT_EQ(imu.mount_tilts_deg.size(), 1u);
    EXPECT_EQ(imu.mount_tilts_deg[0], 15);
    // SisFall's board: y down, z out of the belly (forwards). Tilted 15 deg, z reads -g sin 15 deg, y -g cos 15 deg.
    const Vector3d a = imu.signals[0].acc[10];
    EXPECT_NEAR(a.z(), -kGravity * std::sin(15 * M_PI / 180), 1e-3);
    EXPECT_NEAR(a.y(), -kGravity * std::cos(15 * M_PI / 180), 1e-3);
    m.tilt.sd_deg = 5;  // drawn per recording: seeded, and different between seeds
    EXPECT_EQ(draw_tilt_deg(m, 3), draw_tilt_deg(m, 3));
    EXPECT_NE(draw_tilt_deg(m, 3), draw_tilt_deg(m, 4));
}

TEST(Realism, TheBeltRunsAcrossTheBellyWhateverTheTilt) {
    // SisFall's board sits on the belt at the front (x across the body, y down, z forwards): its strap runs
    // along x; tilting it about that same tangent keeps it there.
    const ProceduralBody body(average_man());
    const SensorPlacement board = builtin_placement_set("sisfall").sensors[0];
    for (const double tilt : {0.0, 15.0}) {
        const SensorMount mount = mount_sensor(body, board, tilt);
        EXPECT_NEAR(std::fabs(mount.horizontal_tangent_in_sensor().x()), 1, 1e-9) << tilt;
        EXPECT_NEAR(mount.horizontal_tangent.y(), 0, 1e-12) << tilt;
    }
    // On the side of the hip the belt runs forwards and backwards.
    SensorPlacement side = board;
    side.around_deg = 90;
    EXPECT_GT(std::fabs(mount_sensor(body, side).horizontal_tangent.z()), 0.95);
}

namespace {
// The standing skeleton turning about the vertical through its pelvis, 0.2 rad at 1 Hz, 6 s at 20 fps: the
// pelvis yaws as a whole and the legs and trunk go with it.
JointSequence yawing() {
    const ProceduralBody body(average_man());
    JointSequence s(120, kNumJoints, 20);
    const Vector3d pivot = body.rest_joints()[pelvis];
    for (int f = 0; f < s.num_frames; ++f) {
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(0.2 * std::sin(2 * M_PI * f / 20.0), Vector3d::UnitY()).toRotationMatrix();
        for (int j = 0; j < kNumJoints; ++j) s.at(f, j) = pivot + turn * (body.rest_joints()[j] - pivot);
    }
    return s;
}

// Amplitude of the 1-Hz sine in one axis of a 50 Hz signal over 3 s from 1.5 s.
double one_hertz_amplitude(const std::vector<Vector3d>& x, int axis) {
    double c = 0, s = 0;
    for (size_t k = 75; k < 225; ++k) {
        c += x[k][axis] * std::cos(2 * M_PI * static_cast<double>(k) / 50);
        s += x[k][axis] * std::sin(2 * M_PI * static_cast<double>(k) / 50);
    }
    return 2 * std::hypot(c, s) / 150;
}
}  // namespace

TEST(Realism, TrunkSwayTurnsAndMovesTheWaistTagLessAndLeavesTheAnkleAlone) {
    // UMAFall's tags: ankle (not on the trunk), waist (pelvis, x up, z out of the belly), chest, wrist.
    const std::vector<SensorPlacement> sensors = parse_sensor_sets("umafall");
    const BodyImu ideal = synthesize_body_imu(yawing(), average_man(), sensors, {});
    RealismModel m;
    m.trunk.yaw_gain = 0.5;
    const BodyImu swayed = synthesize_body_imu(yawing(), average_man(), sensors, with(m));
    // The waist tag keeps 0.5 + 0.5 x 0.0072 (what the 0.5 s slow part passes at 1 Hz) of the yaw rate about its
    // x axis (2 pi 0.2 = 1.26 rad/s as bolted), and of its tangential acceleration across the belly (y): the
    // lever arm turns with it.
    const double kept = 0.5 + 0.5 * std::exp(-std::pow(2 * M_PI * 0.5, 2) / 2);
    EXPECT_NEAR(one_hertz_amplitude(ideal.signals[1].gyr, 0), 2 * M_PI * 0.2, 0.02);
    EXPECT_NEAR(one_hertz_amplitude(swayed.signals[1].gyr, 0) / one_hertz_amplitude(ideal.signals[1].gyr, 0), kept,
                0.01);
    EXPECT_GT(one_hertz_amplitude(ideal.signals[1].acc, 1), 0.3);
    EXPECT_NEAR(one_hertz_amplitude(swayed.signals[1].acc, 1) / one_hertz_amplitude(ideal.signals[1].acc, 1), kept,
                0.02);
    for (size_t k = 0; k < ideal.signals[0].acc.size(); ++k) {  // the ankle's track is its own
        EXPECT_EQ(ideal.signals[0].acc[k], swayed.signals[0].acc[k]);
        EXPECT_EQ(ideal.signals[0].gyr[k], swayed.signals[0].gyr[k]);
    }
}

TEST(Realism, TempoPlaysTheSameMotionFasterOrSlower) {
    RealismModel m;
    m.tempo_log_sd = 0.2;
    const JointSequence motion = hopping();
    const BodyImu imu = synthesize_body_imu(motion, average_man(), parse_sensor_sets("sisfall"), with(m));
    EXPECT_NE(imu.tempo, 1.0);
    const double seconds = (motion.num_frames - 1) / (20.0 * imu.tempo);
    EXPECT_EQ(imu.signals[0].t.size(), static_cast<size_t>(std::floor(seconds * 50 + 1e-9)) + 1);
    // The log tempo over many seeds has the set sd.
    double sum = 0, sum2 = 0;
    for (uint64_t seed = 0; seed < 4000; ++seed) {
        const double l = std::log(draw_tempo(m, seed));
        sum += l, sum2 += l * l;
    }
    EXPECT_NEAR(std::sqrt(sum2 / 4000 - std::pow(sum / 4000, 2)), 0.2, 0.01);
}

TEST(Realism, LandingsMakeTheAttachmentRingAboveThreeHertz) {
    const JointSequence motion = hopping();
    const std::vector<SensorPlacement> waist = parse_sensor_sets("sisfall");
    const BodyImu ideal = synthesize_body_imu(motion, average_man(), waist, {});
    RealismModel m;
    m.tissue = {8, 0.3};
    m.landings.gain_m_s = 1;
    const BodyImu soft = synthesize_body_imu(motion, average_man(), waist, with(m));
    ASSERT_EQ(ideal.signals[0].acc.size(), soft.signals[0].acc.size());
    // The mean reading is kept (the pulses carry no net velocity change: gravity and the bounce stay).
    EXPECT_NEAR(mean_y(soft.signals[0], 0), mean_y(ideal.signals[0], 0), 0.05);
    // Sample-to-sample changes (a high-pass view) grow: the landings ring.
    double d_ideal = 0, d_soft = 0;
    for (size_t k = 1; k < soft.signals[0].acc.size(); ++k) {
        d_ideal += (ideal.signals[0].acc[k] - ideal.signals[0].acc[k - 1]).squaredNorm();
        d_soft += (soft.signals[0].acc[k] - soft.signals[0].acc[k - 1]).squaredNorm();
    }
    EXPECT_GT(d_soft, 2 * d_ideal);
}

TEST(Realism, PresetsAndTomlFilesAreReadStrictly) {
    for (const std::string& name : realism_preset_names()) EXPECT_NO_THROW(realism_preset(name).validate(name)) << name;
    EXPECT_THROW(parse_realism("sisfal"), Error);
    const RealismModel m = parse_realism_toml("base = \"sisfall\"\ntilt_deg = 20\ntissue_hz = 0\n", "mine.toml");
    EXPECT_EQ(m.tilt.mean_deg, 20);
    EXPECT_FALSE(m.tissue.enabled());
    EXPECT_EQ(m.sensor, "sisfall");  // kept from the base
    EXPECT_EQ(m.name, "mine.toml");
    EXPECT_THROW(parse_realism_toml("tilt_dg = 3\n", "mine.toml"), Error);
    EXPECT_THROW(parse_realism_toml("tempo_sd = 2\n", "mine.toml"), Error);
    // An unknown sensor model is refused where the model is used, naming the file and the key.
    const std::string phone = test::error_message(
        [] { VirtualImuOptions().set_realism(parse_realism_toml("sensor = \"phone\"\n", "mine.toml")); });
    EXPECT_TRUE(test::contains(phone, "mine.toml: sensor") && test::contains(phone, "phone")) << phone;
    // +sensor=MODEL sets the sensor key, last, its overrides' signs kept; the levers before it as without it.
    EXPECT_EQ(parse_realism("none+sensor=smartphone").sensor, "smartphone");
    const RealismModel with_sensor = parse_realism("sisfall-tilt+sensor=umafall,acc_noise_density=1e-3,scale_sd=0");
    EXPECT_EQ(with_sensor.sensor, "umafall,acc_noise_density=1e-3,scale_sd=0");
    EXPECT_EQ(with_sensor.tilt.sd_deg, parse_realism("sisfall-tilt").tilt.sd_deg);
    EXPECT_EQ(with_sensor.name, "sisfall-tilt+sensor=umafall,acc_noise_density=1e-3,scale_sd=0");
    const std::string e =
        test::error_message([] { VirtualImuOptions().set_realism(parse_realism("sisfall+sensor=phone")); });
    EXPECT_TRUE(test::contains(e, "sensor") && test::contains(e, "phone")) << e;
    EXPECT_THROW(VirtualImuOptions().set_realism(parse_realism("none+sensor=")), Error);
}

namespace {
std::string realism_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}
bool mentions(const std::string& m, const std::string& part) { return m.find(part) != std::string::npos; }
}  // namespace

TEST(Realism, PresetsTurnOnOnlyTiltAndTheirOwnDevice) {
    // realism.hpp: "none" is the ideal sensor; landings, soft tissue and tempo are off in every preset; each
    // other preset uses the device model of the same name; the calibrated ones spread the tilt over recordings.
    EXPECT_EQ(realism_preset_names(),
              (std::vector<std::string>{"none", "realworld", "sisfall", "umafall", "hugadb", "smartphone"}));
    const RealismModel none = realism_preset("none");
    EXPECT_EQ(none.tilt.mean_deg, 0);
    EXPECT_EQ(none.tilt.sd_deg, 0);
    EXPECT_EQ(none.sensor, "none");
    for (const std::string& name : realism_preset_names()) {
        const RealismModel m = realism_preset(name);
        EXPECT_EQ(m.name, name);
        EXPECT_EQ(m.sensor, name);
        EXPECT_FALSE(m.tissue.enabled()) << name;
        EXPECT_FALSE(m.strap.enabled()) << name;
        for (const RealismLever& lever : realism_levers()) {
            if (std::string(lever.name) != "tilt" && std::string(lever.name) != "sensor") {
                EXPECT_FALSE(lever.enabled(m)) << name << " " << lever.name;
            }
        }
        EXPECT_NO_THROW(parse_noise_model(m.sensor)) << name;
    }
    EXPECT_GT(realism_preset("sisfall").tilt.sd_deg, 0);
    EXPECT_GT(realism_preset("umafall").tilt.sd_deg, 0);
    const std::string m = realism_error([] { realism_preset("sisfal"); });
    EXPECT_TRUE(mentions(m, "--realism") && mentions(m, "sisfal")) << m;
}

TEST(Realism, DrawsFollowTheModelsDistributions) {
    RealismModel m;
    m.tilt.mean_deg = 7.5;
    EXPECT_EQ(draw_tilt_deg(m, 1), 7.5);  // no spread: the mean itself
    EXPECT_EQ(draw_tempo(m, 1), 1.0);     // no tempo spread: the motion as it is
    m.tilt.sd_deg = 10;
    double sum = 0, sum2 = 0;
    const int n = 4000;
    for (int seed = 0; seed < n; ++seed) {
        const double t = draw_tilt_deg(m, static_cast<uint64_t>(seed));
        sum += t, sum2 += t * t;
    }
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 7.5, 4 * 10 / std::sqrt(double(n)));
    EXPECT_NEAR(sd, 10, 0.5);
}

TEST(Realism, ValidationNamesTheKeyOutOfRange) {
    const std::pair<const char*, std::function<void(RealismModel&)>> cases[] = {
        {"tilt_deg", [](RealismModel& m) { m.tilt.mean_deg = 91; }},
        {"tilt_deg", [](RealismModel& m) { m.tilt.mean_deg = NAN; }},
        {"tilt_sd_deg", [](RealismModel& m) { m.tilt.sd_deg = -1; }},
        {"impact_gain", [](RealismModel& m) { m.landings.gain_m_s = 11; }},
        {"impact_ms", [](RealismModel& m) { m.landings.duration_ms = 4; }},
        {"tempo_sd", [](RealismModel& m) { m.tempo_log_sd = 0.6; }},
        {"impact_size_sd", [](RealismModel& m) { m.landings.spread.size_sd = 1.5; }},
        {"impact_horizontal_sd", [](RealismModel& m) { m.landings.spread.horizontal_sd = -0.1; }},
        {"vibration_gain", [](RealismModel& m) { m.vibration.gain = 1.5; }},
        {"vibration_high_hz", [](RealismModel& m) { m.vibration.high_hz = 4; }},
        {"sensor_rate_hz", [](RealismModel& m) { m.sensor_sample_rate_hz = 3; }},
        {"trunk_pitch_gain", [](RealismModel& m) { m.trunk.pitch_gain = 2.5; }},
        {"trunk_yaw_gain", [](RealismModel& m) { m.trunk.yaw_gain = -1.5; }},
        {"trunk_sigma_s", [](RealismModel& m) { m.trunk.sigma_s = 0; }},
        {"strap_hz", [](RealismModel& m) { m.strap.frequency_hz = 0.5; }},
        {"strap_damping",
         [](RealismModel& m) {
             m.strap = {6, 0};
         }},
        {"tissue_damping",
         [](RealismModel& m) {
             m.tissue = {6, 3};
         }},
    };
    for (const auto& [key, spoil] : cases) {
        RealismModel m;
        EXPECT_NO_THROW(m.validate("mine.toml"));
        spoil(m);
        const std::string e = realism_error([&] { m.validate("mine.toml"); });
        EXPECT_TRUE(mentions(e, "mine.toml") && mentions(e, key)) << key << ": " << e;
    }
    const std::string e = realism_error([] { parse_realism_toml("tilt_deg = \"steep\"\n", "typed.toml"); });
    EXPECT_TRUE(mentions(e, "typed.toml") && mentions(e, "tilt_deg") && mentions(e, "a number")) << e;
}

TEST(Realism, JsonFormReadsBackAsTheSameModel) {
    RealismModel m = realism_preset("umafall");
    m.tilt.mean_deg = -4.5;
    m.tissue = {9, 0.4};
    m.strap = {5.5, 0.3};
    m.landings = {0.8, 30, {0.3, 0.7}};
    m.tempo_log_sd = 0.1;
    m.trunk = {0.4, 0.6, 0.7};
    m.vibration = {0.2, 4, 11};
    m.sensor_sample_rate_hz = 20;
    const nlohmann::json j = m.to_json();
    // Every key but the name as a TOML file, from the "none" base: the same model.
    std::string toml;
    for (const auto& [key, value] : j.items())
        if (key != "name") toml += key + " = " + value.dump() + "\n";
    const std::string dir = test::scratch_dir("realism_json");
    const std::string path = dir + "/model.toml";
    std::ofstream(path) << toml;
    const RealismModel back = parse_realism(path);
    EXPECT_EQ(back.name, path);
    nlohmann::json expected = j, got = back.to_json();
    expected.erase("name");
    got.erase("name");
    EXPECT_EQ(got, expected) << toml;
    const std::string e = realism_error([&] { parse_realism(dir + "/absent.toml"); });
    EXPECT_TRUE(mentions(e, dir + "/absent.toml")) << e;
}

TEST(RealismTable, OffValuesAreTheDefaultsAndCalibratedValuesTurnEachLeverOn) {
    for (const RealismLever& lever : realism_levers()) {
        RealismModel m;
        EXPECT_FALSE(lever.enabled(m)) << lever.name;
        for (const RealismKey& k : lever.keys) {
            if (k.number) {
                EXPECT_EQ(k.number(m), k.off) << k.key;
            }
        }
        const RealismModel on = parse_realism(std::string("none+") + lever.name);  // validated
        EXPECT_TRUE(lever.enabled(on)) << lever.name;
        for (const RealismLever& other : realism_levers()) {  // and nothing else
            if (&other != &lever) {
                EXPECT_FALSE(other.enabled(on)) << lever.name << " turned on " << other.name;
            }
        }
    }
}

TEST(RealismTable, VariantsSpellAPresetWithLeversOnAndOff) {
    const RealismModel strap = parse_realism("sisfall+strap+vibration");
    EXPECT_EQ(strap.name, "sisfall+strap+vibration");
    EXPECT_EQ(strap.tilt.mean_deg, 7.5);  // the preset's
    EXPECT_EQ(strap.sensor, "sisfall");
    EXPECT_EQ(strap.strap.frequency_hz, 6);  // calibrated on SisFall walking's lateral spectrum
    EXPECT_EQ(strap.strap.damping_ratio, 0.25);
    EXPECT_EQ(strap.vibration.gain, 0.15);
    const RealismModel tilt_alone = parse_realism("sisfall-sensor");
    EXPECT_EQ(tilt_alone.sensor, "none");
    EXPECT_EQ(tilt_alone.tilt.sd_deg, 10);
    const RealismModel device_alone = parse_realism("umafall-tilt");
    EXPECT_EQ(device_alone.tilt.sd_deg, 0);
    EXPECT_EQ(device_alone.sensor, "umafall");
    for (const char* bad : {"sisfall+wobble", "sisfall+", "nonesuch+tilt", "+tilt"}) {
        const std::string e = realism_error([&] { parse_realism(bad); });
        EXPECT_TRUE(mentions(e, "--realism")) << bad << ": " << e;
    }
    EXPECT_TRUE(mentions(realism_error([] { parse_realism("sisfall+wobble"); }), "wobble"));
}

TEST(RealismTable, TheHelpNamesEveryLeverAndKeyWithItsRange) {
    const std::string help = realism_help();
    for (const std::string& preset : realism_preset_names()) EXPECT_TRUE(mentions(help, preset)) << preset;
    for (const RealismLever& lever : realism_levers()) {
        EXPECT_TRUE(mentions(help, std::string(lever.name) + " (" + realism_stage_name(lever.stage) + ")"))
            << lever.name;
        for (const RealismKey& k : lever.keys)
            EXPECT_TRUE(mentions(help, std::string("      ") + k.key + ": ")) << k.key;
    }
    EXPECT_TRUE(mentions(help, "tilt_deg: -90 to 90 deg; off 0, calibrated 7.5")) << help;
    EXPECT_TRUE(mentions(help, "sensor_rate_hz: 0 (off) or 5 to 2000 Hz, whole")) << help;
    // The experimental tier: a lever no preset turns on is listed after its heading, the presets' levers before it.
    const size_t tier = help.find("Experimental levers");
    ASSERT_NE(tier, std::string::npos) << help;
    for (const RealismLever& lever : realism_levers()) {
        bool in_a_preset = false;
        for (const std::string& preset : realism_preset_names())
            in_a_preset = in_a_preset || lever.enabled(realism_preset(preset));
        EXPECT_EQ(realism_lever_experimental(lever), !in_a_preset) << lever.name;
        EXPECT_EQ(help.find(std::string("\n  ") + lever.name + " (") > tier, !in_a_preset) << lever.name;
    }
    EXPECT_TRUE(realism_lever_experimental(realism_lever("strap")));
    EXPECT_FALSE(realism_lever_experimental(realism_lever("tilt")));
    // Both commands that take --realism show it.
    for (const char* command : {"synth --help", "imu synth --help"}) {
        const test::CliResult r = test::run_cli(command);
        for (const RealismLever& lever : realism_levers())
            for (const RealismKey& k : lever.keys) EXPECT_TRUE(mentions(r.output, k.key)) << command << " " << k.key;
    }
}

TEST(RealismTable, ARetiredLeverRecordedOffReadsAsTodaysModel) {
    nlohmann::json old = realism_preset("sisfall").to_json();
    old["roll_gain"] = 1;  // the device roll, retired on 2026-12-05, recorded off
    old["roll_sigma_s"] = 0.5;
    old.erase("vibration_gain");  // a lever added since: absent reads as off
    EXPECT_EQ(realism_record_as_today(old), realism_preset("sisfall").to_json());
    old["roll_gain"] = 0;  // recorded on: no model of today equals it
    EXPECT_NE(realism_record_as_today(old), realism_preset("sisfall").to_json());
    // The sensor model's keys were "device" and "device_rate_hz" (a word the torch device also uses): they read
    // under today's names.
    nlohmann::json renamed = realism_preset("sisfall").to_json();
    renamed["device"] = renamed["sensor"];
    renamed["device_rate_hz"] = renamed["sensor_rate_hz"];
    renamed.erase("sensor");
    renamed.erase("sensor_rate_hz");
    EXPECT_EQ(realism_record_as_today(renamed), realism_preset("sisfall").to_json());
}

TEST(RealismTable, EveryKeyIsWrittenInAtMostTwoFilesOfTheLibrary) {
    // Its table entry (realism.cpp) and at most the stage that records its draw (virtual_imu.cpp). "sensor" is
    // also the word for every placed sensor, so it is not counted.
    namespace fs = std::filesystem;
    std::vector<std::pair<std::string, std::string>> sources;  // file name, text: read once for every key
    for (const auto& e : fs::recursive_directory_iterator(fs::path(T2IMU_SOURCE_DIR) / "src")) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path());
        sources.emplace_back(e.path().filename().string(),
                             std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
    }
    for (const RealismLever& lever : realism_levers())
        for (const RealismKey& k : lever.keys) {
            if (std::string(k.key) == "sensor") continue;
            const std::regex word(std::string("\\b") + k.key + "\\b");
            std::vector<std::string> files;
            for (const auto& [name, text] : sources)
                if (std::regex_search(text, word)) files.push_back(name);
            EXPECT_LE(files.size(), 2u) << k.key << " in " << ::testing::PrintToString(files);
        }
}
