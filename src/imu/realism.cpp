#include "imu/realism.hpp"

#include <atomic>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/toml_section.hpp"
#include "imu/dataset_profile.hpp"

namespace t2imu {

namespace {

std::string preset_names_text();  // "none, realworld, ..., smartphone": below, with the presets

std::string format_number(double v) {  // 7.5, 0.25, 2000: as a user writes it
    std::ostringstream s;
    s << v;
    return s.str();
}

// A number key: range [lo, hi], 0 also valid when zero_is_off, whole numbers only when whole.
RealismKey number(const char* key, const char* unit, double lo, double hi, double off, double on,
                  double& (*field)(RealismModel&), bool zero_is_off = false, bool whole = false) {
    return {key, unit, lo, hi, zero_is_off, whole, off, on, field, nullptr, nullptr};
}

// A damping ratio, and a frequency and damping the integration stays stable with (soft_tissue.hpp; the bound is
// derived in docs/realism.md): an overdamped mode's fast root grows without bound in RK4 at 1 kHz otherwise.
void check_damping(const SoftTissue& mode, const char* key, const char* hz_key, const std::string& source) {
    if (mode.enabled() && !(mode.damping_ratio > 0))
        throw Error(source, key, "a damping ratio in (0, 2] when its frequency is on",
                    std::to_string(mode.damping_ratio));
    if (mode.enabled() && rk4_growth_per_step(mode, 1 / kAttachmentRateHz) > 1)
        throw Error(source, std::string(hz_key) + " with " + key,
                    "2 pi " + std::string(hz_key) +
                        " (zeta + sqrt(zeta^2 - 1)) at most 2785 per second (stable at the 1 kHz integration rate)",
                    format_number(mode.frequency_hz) + " Hz with " + format_number(mode.damping_ratio));
}

// The levers in the order their stages run. "on" is the value each was calibrated or measured with
// (docs/realism.md): tilt on the shared SisFall walking trials (the sisfall preset's), soft tissue from the
// wobbling-mass literature (soft_tissue.hpp), the strap on SisFall walking's lateral spectrum, landings on SisFall
// walking's share of power above 3 Hz (0.30 -> 0.47), their spread and tempo as measured in the first ablations,
// the trunk sway on SisFall walking's gyroscope, body vibration on SisFall's 5-10 Hz band, the device rate at
// UMAFall's tags' 20 Hz (where it moved the texture), the sensor model as the sisfall preset's.
//
// Measured and retired (the rule: a lever stays if it improves a measured fidelity figure on at least one real
// data set, or models a documented device behaviour a user can choose): the device roll (`roll_gain`,
// `roll_sigma_s`: the share of its segment's frontal-plane sway a device rolls with), which made synthetic data
// easier to tell from real and lowered HAR (docs/realism.md on device roll and drawn bodies). Its keys,
// recorded off (gain 1) in folders made before its retirement, read as today's models.
const std::vector<RealismLever> kLevers = {
    {"tempo",
     RealismStage::motion,
     "the motion played at its frame rate x exp(N(0, tempo_sd)) per recording: a uniform time warp",
     {number("tempo_sd", "", 0, 0.5, 0, 0.08, [](RealismModel& m) -> double& { return m.tempo_log_sd; })},
     [](const RealismModel& m) { return m.tempo_log_sd > 0; },
     nullptr},
    {"trunk",
     RealismStage::body,
     "a trunk sensor turns with this share of its segment's sway about the left-right (pitch) and long (yaw) axes, the "
     "slow part kept",
     {number("trunk_pitch_gain", "", -1, 2, 1, 0.35, [](RealismModel& m) -> double& { return m.trunk.pitch_gain; }),
      number("trunk_yaw_gain", "", -1, 2, 1, 0.6, [](RealismModel& m) -> double& { return m.trunk.yaw_gain; }),
      number("trunk_sigma_s", "s", 0.1, 5, 0.5, 0.5, [](RealismModel& m) -> double& { return m.trunk.sigma_s; })},
     [](const RealismModel& m) { return m.trunk.enabled(); },
     nullptr},
    {"tilt",
     RealismStage::mount,
     "the sensor turned about the skin's horizontal tangent, outward normal down, N(mean, sd) per recording",
     {number("tilt_deg", "deg", -90, 90, 0, 7.5, [](RealismModel& m) -> double& { return m.tilt.mean_deg; }),
      number("tilt_sd_deg", "deg", 0, 45, 0, 10, [](RealismModel& m) -> double& { return m.tilt.sd_deg; })},
     [](const RealismModel& m) { return m.tilt.mean_deg != 0 || m.tilt.sd_deg > 0; },
     nullptr},
    {"tissue",
     RealismStage::attachment,
     "the attachment a damped spring-mass on the body point, translation and rotation (1 kHz)",
     {number(
          "tissue_hz", "Hz", 1, 200, 0, 10, [](RealismModel& m) -> double& { return m.tissue.frequency_hz; }, true),
      number("tissue_damping", "", 0, 2, 0, 0.5, [](RealismModel& m) -> double& { return m.tissue.damping_ratio; })},
     [](const RealismModel& m) { return m.tissue.enabled(); },
     [](const RealismModel& m, const std::string& source) {
         check_damping(m.tissue, "tissue_damping", "tissue_hz", source);
     }},
    {"strap",
     RealismStage::attachment,
     "the device sliding along its belt or strap: a spring-mass along the skin's horizontal tangent",
     {number(
          "strap_hz", "Hz", 1, 200, 0, 6, [](RealismModel& m) -> double& { return m.strap.frequency_hz; }, true),
      number("strap_damping", "", 0, 2, 0, 0.25, [](RealismModel& m) -> double& { return m.strap.damping_ratio; })},
     [](const RealismModel& m) { return m.strap.enabled(); },
     [](const RealismModel& m, const std::string& source) {
         check_damping(m.strap, "strap_damping", "strap_hz", source);
     }},
    {"landings",
     RealismStage::attachment,
     "each foot landing's sharp velocity change at the shank (m/s), scaled by transmissibility to the sensor's segment",
     {number("impact_gain", "m/s", 0, 10, 0, 0.8, [](RealismModel& m) -> double& { return m.landings.gain_m_s; }),
      number("impact_ms", "ms", 5, 200, 40, 40, [](RealismModel& m) -> double& { return m.landings.duration_ms; })},
     [](const RealismModel& m) { return m.landings.enabled(); },
     nullptr},
    {"spread",
     RealismStage::attachment,
     "landings differ: log-normal size and horizontal components per landing",
     {number("impact_size_sd", "", 0, 1, 0, 0.3, [](RealismModel& m) -> double& { return m.landings.spread.size_sd; }),
      number("impact_horizontal_sd", "", 0, 2, 0, 0.8,
             [](RealismModel& m) -> double& { return m.landings.spread.horizontal_sd; })},
     [](const RealismModel& m) { return m.landings.spread.size_sd > 0 || m.landings.spread.horizontal_sd > 0; },
     nullptr},
    {"vibration",
     RealismStage::signal,
     "band-limited noise on the accelerometer, its sd gain x the motion's local rms level",
     {number("vibration_gain", "", 0, 1, 0, 0.15, [](RealismModel& m) -> double& { return m.vibration.gain; }),
      number("vibration_low_hz", "Hz", 0.1, 100, 5, 5, [](RealismModel& m) -> double& { return m.vibration.low_hz; }),
      number("vibration_high_hz", "Hz", 0.1, 200, 12, 12,
             [](RealismModel& m) -> double& { return m.vibration.high_hz; })},
     [](const RealismModel& m) { return m.vibration.enabled(); },
     [](const RealismModel& m, const std::string& source) {
         if (!(m.vibration.high_hz > m.vibration.low_hz))
             throw Error(source, "vibration_high_hz", "above vibration_low_hz", std::to_string(m.vibration.high_hz));
     }},
    {"sensor",
     RealismStage::sensor,
     "the sensor's own errors: noise density, bias, range and resolution of its data sheet",
     {{"sensor", "", 0, 0, false, false, 0, 0, nullptr, [](RealismModel& m) -> std::string& { return m.sensor; },
       "sisfall"}},
     [](const RealismModel& m) { return m.sensor != "none"; },
     nullptr},
    {"rate",
     RealismStage::sensor,
     "the sensor samples at its own rate (what lies above its Nyquist frequency folds in), then resampled",
     {number(
         "sensor_rate_hz", "Hz", 5, 2000, 0, 20, [](RealismModel& m) -> double& { return m.sensor_sample_rate_hz; },
         true, true)},
     [](const RealismModel& m) { return m.sensor_sample_rate_hz > 0; },
     nullptr},
};

// Keys renamed since folders recorded them (the sensor model was "device", a word the torch device also uses).
const std::pair<const char*, const char*> kRenamedKeys[] = {{"device", "sensor"}, {"device_rate_hz", "sensor_rate_hz"}};

// Keys of retired levers and the value that recorded them off.
const std::pair<const char*, double> kRetiredKeys[] = {{"roll_gain", 1}, {"roll_sigma_s", 0.5}};

std::string range_text(const RealismKey& k) {
    std::string r = (k.zero_is_off ? "0 (off) or " : "") + format_number(k.lo) + " to " + format_number(k.hi);
    if (*k.unit) r += std::string(" ") + k.unit;
    return k.whole ? r + ", whole" : r;
}

void check_key(const RealismKey& k, const RealismModel& m, const std::string& source) {
    if (!k.number) return;
    RealismModel copy = m;
    const double v = k.number(copy);
    const bool in_range = (k.zero_is_off && v == 0) || (v >= k.lo && v <= k.hi);
    if (!in_range || (k.whole && v != std::round(v))) throw Error(source, k.key, range_text(k), std::to_string(v));
}

const RealismLever* find_lever(const std::string& name) {
    for (const RealismLever& l : kLevers)
        if (name == l.name) return &l;
    return nullptr;
}

std::string lever_names() {
    std::string names;
    for (const RealismLever& l : kLevers) names += (names.empty() ? "" : ", ") + std::string(l.name);
    return names;
}

void set_lever(const RealismLever& lever, bool on, RealismModel* m) {
    for (const RealismKey& k : lever.keys) {
        if (k.number) k.number(*m) = on ? k.on : k.off;
        if (k.text) k.text(*m) = on ? k.text_on : "none";
    }
}

constexpr const char* kSensorAssignment = "+sensor=";

// PRESET+LEVER-LEVER...: the preset with each +LEVER at its calibrated values and each -LEVER off.
RealismModel parse_variant(const std::string& text) {
    const size_t first = text.find_first_of("+-");
    RealismModel m = realism_preset(text.substr(0, first));
    m.name = text;
    for (size_t at = first; at < text.size();) {
        const size_t next = text.find_first_of("+-", at + 1);
        const std::string name = text.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
        const RealismLever* lever = find_lever(name);
        if (!lever) throw Error("--realism", "lever", lever_names(), name);
        set_lever(*lever, text[at] == '+', &m);
        at = next == std::string::npos ? text.size() : next;
    }
    return m;
}

}  // namespace

const char* realism_stage_name(RealismStage stage) {
    static const char* const names[] = {"motion", "body", "mount", "attachment", "signal", "sensor"};
    return names[static_cast<int>(stage)];
}

const std::vector<RealismLever>& realism_levers() { return kLevers; }

const RealismLever& realism_lever(const std::string& name) {
    const RealismLever* lever = find_lever(name);
    if (!lever) throw std::logic_error("realism_lever: no lever " + name);
    return *lever;
}

void RealismModel::validate(const std::string& source) const {
    for (const RealismLever& lever : kLevers) {
        for (const RealismKey& k : lever.keys) check_key(k, *this, source);
        if (lever.check) lever.check(*this, source);
    }
}

nlohmann::json RealismModel::to_json() const {
    nlohmann::json j = {{"name", name}};
    RealismModel m = *this;
    for (const RealismLever& lever : kLevers)
        for (const RealismKey& k : lever.keys)
            j[k.key] = k.number ? nlohmann::json(k.number(m)) : nlohmann::json(k.text(m));
    return j;
}

nlohmann::json realism_record_as_today(const nlohmann::json& recorded) {
    nlohmann::json today = RealismModel().to_json();
    for (const auto& [key, value] : recorded.items()) {
        bool retired_off = false;
        for (const auto& [retired, off] : kRetiredKeys) retired_off |= key == retired && value == nlohmann::json(off);
        std::string name = key;
        for (const auto& [before, now] : kRenamedKeys)
            if (key == before) name = now;
        if (!retired_off) today[name] = value;
    }
    return today;
}

std::string realism_help() {
    std::string h =
        "realism model: PRESET, PRESET+LEVER-LEVER (levers at their calibrated values / off), either followed by\n"
        "+sensor=MODEL[,key=value...] (the sensor model, last), or FILE.toml (base = \"PRESET\" and keys). Presets: " +
        preset_names_text() + " (none is the default).";
    for (const bool experimental : {false, true}) {
        h += experimental
                 ? "\nExperimental levers, off in every preset (kept by the rule of docs/realism.md#the-levers):"
                 : "\nLevers the presets turn on, and their keys:";
        for (const RealismLever& lever : kLevers) {
            if (realism_lever_experimental(lever) != experimental) continue;
            h += std::string("\n  ") + lever.name + " (" + realism_stage_name(lever.stage) + "): " + lever.physics;
            for (const RealismKey& k : lever.keys) {
                h += std::string("\n      ") + k.key + ": ";
                h += k.number
                         ? range_text(k) + "; off " + format_number(k.off) + ", calibrated " + format_number(k.on)
                         : std::string("none, a sensor model or model,key=value overrides; off none, calibrated ") +
                               k.text_on;
            }
        }
    }
    return h;
}

bool realism_lever_experimental(const RealismLever& lever) {
    for (const std::string& name : realism_preset_names())
        if (lever.enabled(realism_preset(name))) return false;
    return true;
}

namespace {

// The presets (realism.hpp). Only the levers that raised synthetic-only HAR on the shared SisFall subjects are
// on: tilt and the sensor model; each other lever lowered it or left it within its spread (docs/realism.md#the-levers).
struct Preset {
    std::string name;
    double tilt_mean_deg, tilt_sd_deg;
    std::string sensor;
};

// sisfall: the real waist tilt exceeds the synthetic one by 7.5 deg (median mean acc_z while walking, -1.59
//          against -0.30 m/s^2) and spreads by 10 deg over recordings (interquartile range / 1.349).
// umafall: the waist tag's tilt has no common direction (median mean acc_z while walking +0.32 m/s^2) but
//          spreads by 13 deg over recordings.
// hugadb, smartphone: not calibrated (no waist data in the shared HuGaDB copy, no RealWorld data): a strap
//          on a leg turns less than a belt clip (5 deg), a phone in a pocket more (8 deg).
// none, each data set's (dataset_profile.cpp: its tilt, its device), and smartphone: RealWorld's tilt with the generic
// smartphone chip.
std::vector<Preset> presets() {
    std::vector<Preset> out = {{"none", 0, 0, "none"}};
    for (const DatasetProfile& p : dataset_profiles())
        out.push_back({p.name, p.tilt_mean_deg, p.tilt_spread_deg, p.name});
    const DatasetProfile& phones = *find_dataset_profile("realworld");
    out.push_back({"smartphone", phones.tilt_mean_deg, phones.tilt_spread_deg, "smartphone"});
    return out;
}

std::string preset_names_text() {
    std::string names;
    for (const Preset& p : presets()) names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

std::atomic<int64_t> realism_parses{0};  // realism_parse_count()

}  // namespace

std::vector<std::string> realism_preset_names() {
    std::vector<std::string> out;
    for (const Preset& p : presets()) out.push_back(p.name);
    return out;
}

RealismModel realism_preset(const std::string& name) {
    for (const Preset& p : presets()) {
        if (name != p.name) continue;
        RealismModel m;
        m.name = name;
        m.tilt = {p.tilt_mean_deg, p.tilt_sd_deg};
        m.sensor = p.sensor;
        return m;
    }
    throw Error("--realism", "preset", preset_names_text() + " (each +LEVER-LEVER) or a .toml file", name);
}

RealismModel parse_realism_toml(const std::string& text, const std::string& source) {
    const toml::table doc = parse_toml_text(text, source);
    TomlSection top(doc, source, "");
    std::string base = "none";
    top.read("base", base);
    RealismModel m;
    try {
        m = realism_preset(base);
    } catch (const Error&) {  // the file's key is to blame, not --realism
        throw Error(source, "base", preset_names_text(), base);
    }
    m.name = source;
    for (const RealismLever& lever : kLevers)
        for (const RealismKey& k : lever.keys) {
            if (k.number) top.read(k.key, k.number(m));
            if (k.text) top.read(k.key, k.text(m));
        }
    top.refuse_unknown_keys();
    m.validate(source);
    return m;
}

int64_t realism_parse_count() { return realism_parses.load(); }

RealismModel parse_realism(const std::string& text) {
    ++realism_parses;
    if (text.size() > 5 && ends_with(text, ".toml")) return parse_realism_toml(read_file_text(text), text);
    // +sensor=MODEL comes last: a sensor model's overrides may hold signs ("bias_g=-0.01").
    const size_t sensor_at = text.find(kSensorAssignment);
    const std::string levers = text.substr(0, sensor_at);
    RealismModel m = levers.find_first_of("+-") == std::string::npos ? realism_preset(levers) : parse_variant(levers);
    m.name = text;
    if (sensor_at != std::string::npos) m.sensor = text.substr(sensor_at + std::string(kSensorAssignment).size());
    m.validate("--realism " + text);
    return m;
}

double draw_tilt_deg(const RealismModel& model, uint64_t seed) {
    if (model.tilt.sd_deg <= 0) return model.tilt.mean_deg;
    std::mt19937_64 rng(seed);
    return model.tilt.mean_deg + std::normal_distribution<double>(0, model.tilt.sd_deg)(rng);
}

double draw_tempo(const RealismModel& model, uint64_t seed) {
    if (model.tempo_log_sd <= 0) return 1;
    std::mt19937_64 rng(seed);
    return std::exp(std::normal_distribution<double>(0, model.tempo_log_sd)(rng));
}

}  // namespace t2imu
