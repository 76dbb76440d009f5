// The realism model: what stands between an ideal sensor bolted to a moving skeleton and a real recording, in
// levers that are each seeded, switchable and measured on their own (docs/realism.md).
//
// One table holds the levers (realism.cpp, realism_levers()): per lever its name, the stage of
// synthesize_body_imu it acts in (virtual_imu.hpp), its one-line physics, and its keys with unit, range, the
// value that turns it off and the value it was calibrated or measured with. Reading a TOML file, validation, the
// JSON record, the CLI help (realism_help) and the ablation's variants (`PRESET+LEVER-LEVER`) are all made from
// that table, so a key's name is written there and nowhere else in the library.
//
// Presets (realism.cpp gives the figures each value rests on). The ablations on the shared SisFall subjects
// (docs/realism.md) chose the levers: mounting tilt and the device model raised synthetic-only HAR, the others
// lowered it or left it within its spread, so they are off in every preset (the experimental tier,
// realism_lever_experimental):
//   none        everything off: the ideal sensor of the paper's pipeline
//   DATASET     each data set's (dataset_profile.hpp): its mounting tilt and its own device; sisfall's tilt
//               calibrated on the shared SisFall subjects, umafall's spread on the shared UMAFall subjects
//   smartphone  RealWorld's tilt with the generic smartphone device
//
// Spelling a model (`--realism`, the `realism` of an experiment's [synth] and [[real]]):
//   PRESET                       a preset above
//   PRESET+LEVER-LEVER...        the preset with each +LEVER at its calibrated values and each -LEVER off
//                                (e.g. sisfall+strap+vibration, sisfall-sensor: the tilt alone)
//   ...+sensor=MODEL             either of the above with the sensor key set to MODEL (sensor_noise.hpp), last
//   FILE.toml                    `base = "PRESET"` (default none) and any keys of the table; an unknown key is
//                                refused
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "body/trunk_sway.hpp"
#include "imu/body_vibration.hpp"
#include "imu/heel_strike.hpp"
#include "imu/soft_tissue.hpp"

namespace t2imu {

// The mounting tilt: the sensor turned about the skin's horizontal tangent so that its outward normal points
// down (a belt below a belly, a strap on a tapering limb), drawn per recording from a normal distribution.
struct MountingTilt {
    double mean_deg = 0, sd_deg = 0;
};

// Landing transients (heel_strike.hpp): the velocity change of a landing at the shank (m/s) and its duration.
struct LandingTransients {
    double gain_m_s = 0;  // 0 = off
    double duration_ms = 40;
    LandingSpread spread;
    bool enabled() const { return gain_m_s > 0; }
};

struct RealismModel {
    std::string name = "none";
    double tempo_log_sd = 0;  // sd of the log of the per-recording time warp; 0 = the motion as captured
    TrunkSway trunk;
    MountingTilt tilt;
    SoftTissue tissue;
    SoftTissue strap;
    LandingTransients landings;
    BodyVibration vibration;
    std::string sensor = "none";       // the sensor model (sensor_noise.hpp): "none", a preset, overrides
    double sensor_sample_rate_hz = 0;  // the sensor's own sample rate; 0 = sampled at the output rate (device_rate.hpp)

    // Throws Error naming `source` and the key for a value out of range. The sensor model's spelling is parsed, and
    // checked, where the model is used (VirtualImuOptions::set_realism), once.
    void validate(const std::string& source) const;
    nlohmann::json to_json() const;
};

// The stages of synthesize_body_imu, in the order they run (virtual_imu.hpp).
enum class RealismStage { motion, body, mount, attachment, signal, sensor };
const char* realism_stage_name(RealismStage stage);

struct RealismKey {
    const char* key;   // the TOML / JSON key
    const char* unit;  // "" for a ratio or a name
    double lo, hi;     // the valid range (numbers)
    bool zero_is_off;  // 0 is valid besides [lo, hi]
    bool whole;        // a whole number
    double off, on;    // the value that turns the lever off; the value it was calibrated or measured with
    double& (*number)(RealismModel&);     // null for the sensor model's name
    std::string& (*text)(RealismModel&);  // the sensor model's name (off "none", on `text_on`)
    const char* text_on;
};

struct RealismLever {
    const char* name;
    RealismStage stage;
    const char* physics;  // one line
    std::vector<RealismKey> keys;
    bool (*enabled)(const RealismModel&);
    // Checks that tie its keys together (beyond each key's range), naming `source`; may be null.
    void (*check)(const RealismModel&, const std::string& source);
};

const std::vector<RealismLever>& realism_levers();
// The lever of that name (a name of the table; a programming error otherwise).
const RealismLever& realism_lever(const std::string& name);
// Whether no preset turns the lever on: the experimental tier, kept by docs/realism.md's rule but used by no preset.
bool realism_lever_experimental(const RealismLever& lever);
// The --realism help: how to spell a model, the presets, and every lever with its stage, keys, units and ranges,
// the presets' levers first, then the experimental tier.
std::string realism_help();

std::vector<std::string> realism_preset_names();
RealismModel realism_preset(const std::string& name);  // errors name --realism
RealismModel parse_realism_toml(const std::string& text, const std::string& source);
// PRESET, PRESET+LEVER-LEVER, either followed by +sensor=MODEL (sensor_noise.hpp's spelling: the sensor key set to
// it; last, as its overrides may hold signs), or a .toml file's path (errors name --realism or the file).
RealismModel parse_realism(const std::string& text);
// How many times parse_realism has run in this process: tests check that a job parses its spelling once.
int64_t realism_parse_count();
// A model's JSON record (to_json) with the keys a record made before a lever was added, renamed or retired would
// lack or hold: added keys read as their lever off, renamed keys read under today's name (device -> sensor,
// device_rate_hz -> sensor_rate_hz), a retired lever's keys are dropped when they record it off (a record of a
// retired lever on is returned as it is, so it compares unequal to any model of today).
nlohmann::json realism_record_as_today(const nlohmann::json& recorded);

// Per recording draws, deterministic in the seed.
double draw_tilt_deg(const RealismModel& model, uint64_t seed);
double draw_tempo(const RealismModel& model, uint64_t seed);

}  // namespace t2imu
